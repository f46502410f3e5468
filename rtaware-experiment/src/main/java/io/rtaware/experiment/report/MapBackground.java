package io.rtaware.experiment.report;

import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * What {@code trajectories.png} draws behind the paths: a picture of the course (walls and
 * obstacles, row 0 at the north edge) covering a rectangle of the world, and the course's
 * waypoints. The composition root builds one from the scenario; without one the figure shows
 * the paths alone, framed by their own bounds.
 */
public interface MapBackground {

    /** @return the course's picture, if there is one */
    Optional<BufferedImage> image();

    /** @return the rectangle of the world the picture covers, or null without a picture */
    WorldBounds bounds();

    /** @return the waypoints in order, the last being the finish; may be empty */
    List<Point2D.Double> waypoints();

    /** @return a background with nothing: the figure is framed by the trajectories */
    static MapBackground none() {
        return of(null, null, List.of());
    }

    /**
     * @param image the course's picture, or null
     * @param bounds the rectangle it covers (required with a picture)
     * @param waypoints the waypoints, in order
     * @return the background
     */
    static MapBackground of(BufferedImage image, WorldBounds bounds, List<Point2D.Double> waypoints) {
        if (image != null) {
            Objects.requireNonNull(bounds, "bounds are required with an image");
        }
        List<Point2D.Double> points = List.copyOf(waypoints);
        return new MapBackground() {
            @Override
            public Optional<BufferedImage> image() {
                return Optional.ofNullable(image);
            }

            @Override
            public WorldBounds bounds() {
                return bounds;
            }

            @Override
            public List<Point2D.Double> waypoints() {
                return points;
            }
        };
    }
}
