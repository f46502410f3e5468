package io.rtaware.player.protocol;

/**
 * Body of simulation REQ GET_POSE2D / SET_POSE2D and their replies
 * ({@code player_simulation_pose2d_req_t}: name_count, xdr_bytes name, pose2d). Immutable and
 * thread-safe.
 *
 * @param name the simulation model's name, e.g. {@code r0}
 * @param xM x in metres (world frame)
 * @param yM y in metres
 * @param yawRad heading in radians
 */
public record SimulationPose2d(String name, double xM, double yM, double yawRad) {
}
