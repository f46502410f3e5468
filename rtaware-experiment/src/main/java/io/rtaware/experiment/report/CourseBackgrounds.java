package io.rtaware.experiment.report;

import io.rtaware.robot.geometry.Point2d;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioException;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.util.List;

/**
 * The picture of a course drawn behind the experiment's paths: the scenario's map (obstacles
 * dark, free space light) and its waypoints. A scenario that cannot be loaded (a file moved
 * since the experiment) gives no background, and the figure shows the paths alone.
 */
public final class CourseBackgrounds {

    private static final int OCCUPIED_RGB = 0x505050;
    private static final int FREE_RGB = 0xF2F2F2;
    private static final int UNKNOWN_RGB = 0xC8C8C8;

    private CourseBackgrounds() {
    }

    /**
     * @param scenario {@code paper-room} or a scenario file, as given to {@code run}
     * @return the course's background, or {@link MapBackground#none()}
     */
    public static MapBackground forScenario(String scenario) {
        Scenario s;
        try {
            s = ScenarioLoader.load(scenario);
        } catch (ScenarioException | IllegalArgumentException e) {
            return MapBackground.none();
        }
        List<Point2D.Double> waypoints = s.waypoints().stream().map(CourseBackgrounds::point).toList();
        if (s.map().isEmpty()) {
            return MapBackground.of(null, null, waypoints);
        }
        OccupancyMap map = s.map().get();
        BufferedImage image = new BufferedImage(map.widthCells(), map.heightCells(), BufferedImage.TYPE_INT_RGB);
        for (int row = 0; row < map.heightCells(); row++) {
            for (int col = 0; col < map.widthCells(); col++) {
                int rgb = switch (map.state(col, row)) {
                    case OCCUPIED -> OCCUPIED_RGB;
                    case FREE -> FREE_RGB;
                    case UNKNOWN -> UNKNOWN_RGB;
                };
                image.setRGB(col, map.heightCells() - 1 - row, rgb);
            }
        }
        WorldBounds bounds = new WorldBounds(map.originXM(), map.originYM(),
                map.originXM() + map.widthM(), map.originYM() + map.heightM());
        return MapBackground.of(image, bounds, waypoints);
    }

    private static Point2D.Double point(Point2d p) {
        return new Point2D.Double(p.xM(), p.yM());
    }
}
