package io.rtaware.robot.msg;

import io.rtaware.core.data.Key;

/**
 * The keys through which the robot's sensors and motors are shared: produced and consumed by
 * the Player data task, the behaviors and the mediator. Names are part of the reports.
 */
public final class RobotKeys {

    /** Latest laser scan, produced by the Player data task. */
    public static final Key<LaserScan> LASER = Key.of("laser", LaserScan.class, LaserScan::new);
    /** Latest odometry (pose, velocity, stall), produced by the Player data task. */
    public static final Key<Odometry> ODOMETRY = Key.of("odometry", Odometry.class, Odometry::new);
    /** The mediated motor command, produced by the position mediator, sent by the Player data task. */
    public static final Key<VelocityCommand> MOTOR = Key.of("motor", VelocityCommand.class, VelocityCommand::new);
    /** The position mediator's decision of each cycle: whose request went to the motors ({@link #MOTOR}). */
    public static final Key<MediatorDecision> MEDIATOR_DECISION =
            Key.of("mediator.decision", MediatorDecision.class, MediatorDecision::new);
    /** Motion request of the obstacle avoider. */
    public static final Key<MotionRequest> MOTION_AVOID =
            Key.of("motion.avoid", MotionRequest.class, MotionRequest::new);
    /** Motion request of the waypoint planner. */
    public static final Key<MotionRequest> MOTION_WAYPOINT =
            Key.of("motion.waypoint", MotionRequest.class, MotionRequest::new);

    private RobotKeys() {
    }
}
