package io.rtaware.record;

import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.value.PlanarTransform;

/**
 * The recording plan of a mobile robot, in one place for every run that records or shows a robot
 * ({@code rtaware run --record}, {@code sim --foxglove}, a user's controller): the robot's keys on
 * the topics ROS 2 tools expect, in REP 105 frames ({@link RobotTopics}):
 * {@link RobotKeys#LASER} on {@value RobotTopics#SCAN} (frame {@value RobotTopics#LASER_FRAME}),
 * {@link RobotKeys#ODOMETRY} on {@value RobotTopics#ODOM} (frame {@value RobotTopics#ODOM_FRAME},
 * and each sample as the transform {@value RobotTopics#ODOM_FRAME} to
 * {@value RobotTopics#BASE_FRAME} on {@value RobotTopics#TF}), {@link RobotKeys#MOTOR} on
 * {@value RobotTopics#CMD_VEL}, the true pose on {@value RobotTopics#GROUND_TRUTH} (and as
 * {@value RobotTopics#MAP_FRAME} to {@value RobotTopics#GROUND_TRUTH_FRAME} on
 * {@value RobotTopics#TF}), and on {@value RobotTopics#TF_STATIC} the transforms of
 * {@link RobotTopics#STATIC_TRANSFORMS}. A key the recorder is not given is simply not recorded.
 * Add a controller's own topics and the run's metadata to the plan it returns. Stateless.
 */
public final class RobotRecordingPlan {

    private RobotRecordingPlan() {
    }

    /** @return a new plan with the robot's topics, frames and transforms */
    public static RecordingPlan create() {
        RecordingPlan plan = new RecordingPlan()
                .topic(RobotKeys.LASER.name(), RobotTopics.SCAN, RobotTopics.LASER_FRAME)
                .topic(RobotKeys.ODOMETRY.name(), RobotTopics.ODOM, RobotTopics.ODOM_FRAME)
                .topic(RobotKeys.MOTOR.name(), RobotTopics.CMD_VEL, RobotTopics.BASE_FRAME)
                .withGroundTruth()
                .transformsFrom(RobotKeys.ODOMETRY.name(), RobotTopics.ODOM_FRAME, RobotTopics.BASE_FRAME);
        for (PlanarTransform t : RobotTopics.STATIC_TRANSFORMS) {
            plan.staticTransform(t.parent(), t.child(), t.xM(), t.yM(), t.yawRad());
        }
        return plan;
    }
}
