package io.rtaware.player.protocol;

import java.util.List;

/**
 * Reply to ranger REQ GET_GEOM ({@code player_ranger_geom_t}). Immutable and thread-safe.
 *
 * @param pose pose of the sensor relative to the robot
 * @param size the sensor's extent
 * @param elementPoses pose of each element (may be empty)
 * @param elementSizes size of each element (may be empty)
 */
public record RangerGeometry(Pose3d pose, Bbox3d size, List<Pose3d> elementPoses, List<Bbox3d> elementSizes) {

    /**
     * Copies the lists so the record is immutable.
     *
     * @param pose pose of the sensor relative to the robot
     * @param size the sensor's extent
     * @param elementPoses pose of each element (may be empty)
     * @param elementSizes size of each element (may be empty)
     */
    public RangerGeometry {
        elementPoses = List.copyOf(elementPoses);
        elementSizes = List.copyOf(elementSizes);
    }
}
