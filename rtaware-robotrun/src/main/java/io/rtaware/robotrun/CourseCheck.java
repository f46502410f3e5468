package io.rtaware.robotrun;

import io.rtaware.robot.geometry.Point2d;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Locale;

/**
 * Looks at a course before it is driven and says what cannot work: the start or a waypoint off
 * the map, inside an obstacle, or in a region that no free path connects to the start (an
 * enclosed room). These are warnings, not errors: the run still goes, so that such cases can be
 * studied. Reachability is a 4-connected flood fill over the map's non-obstacle cells from the
 * start's cell (the robot's size is not taken into account, so a gap narrower than the robot
 * still counts as a way through). Needs the scenario's map; without one there is nothing to check.
 * Stateless.
 */
public final class CourseCheck {

    private CourseCheck() {
    }

    /**
     * @param scenario the course
     * @return one sentence per problem, in course order; empty when the course looks drivable
     */
    public static List<String> warnings(Scenario scenario) {
        List<String> warnings = new ArrayList<>();
        OccupancyMap map = scenario.map().orElse(null);
        if (map == null) {
            return warnings;
        }
        Point2d start = scenario.start().position();
        String startProblem = placement(map, start);
        if (startProblem != null) {
            warnings.add("the start pose " + at(start) + " lies " + startProblem);
        }
        BitSet reachable = startProblem == null ? reachableFrom(map, map.colOf(start.xM()), map.rowOf(start.yM())) : null;
        List<Point2d> waypoints = scenario.waypoints();
        for (int i = 0; i < waypoints.size(); i++) {
            Point2d w = waypoints.get(i);
            String problem = placement(map, w);
            if (problem == null && reachable != null
                    && !reachable.get(map.rowOf(w.yM()) * map.widthCells() + map.colOf(w.xM()))) {
                problem = "in a region enclosed from the start (no free path on the map leads there)";
            }
            if (problem != null) {
                warnings.add("waypoint " + (i + 1) + " " + at(w) + " lies " + problem);
            }
        }
        return warnings;
    }

    private static String placement(OccupancyMap map, Point2d p) {
        if (!Double.isFinite(p.xM()) || !Double.isFinite(p.yM()) || !map.inside(map.colOf(p.xM()), map.rowOf(p.yM()))) {
            return String.format(Locale.ROOT, "off the map (it spans x %.2f..%.2f m, y %.2f..%.2f m)", map.originXM(),
                    map.originXM() + map.widthM(), map.originYM(), map.originYM() + map.heightM());
        }
        if (map.isObstacleAt(p.xM(), p.yM())) {
            return "inside an obstacle";
        }
        return null;
    }

    private static BitSet reachableFrom(OccupancyMap map, int col, int row) {
        int width = map.widthCells();
        int cells = width * map.heightCells();
        BitSet seen = new BitSet(cells);
        int[] queue = new int[cells];
        int head = 0;
        int tail = 0;
        queue[tail++] = row * width + col;
        seen.set(row * width + col);
        int[][] steps = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        while (head < tail) {
            int cell = queue[head++];
            int c = cell % width;
            int r = cell / width;
            for (int[] s : steps) {
                int nc = c + s[0];
                int nr = r + s[1];
                int next = nr * width + nc;
                if (map.inside(nc, nr) && !seen.get(next) && !map.isObstacle(nc, nr)) {
                    seen.set(next);
                    queue[tail++] = next;
                }
            }
        }
        return seen;
    }

    private static String at(Point2d p) {
        return String.format(Locale.ROOT, "(%.2f, %.2f)", p.xM(), p.yM());
    }
}
