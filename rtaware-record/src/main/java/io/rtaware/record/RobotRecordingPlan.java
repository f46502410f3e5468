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
 * {@value RobotTopics#CMD_VEL}, and on {@value RobotTopics#TF_STATIC} the transforms of
 * {@link RobotTopics#STATIC_TRANSFORMS}. A key the recorder is not given is simply not recorded.
 * Add a controller's own topics and the run's metadata to the plan it returns, and
 * {@link RecordingPlan#withGroundTruth()} where something knows the true pose (a simulator):
 * a robot's own odometry is not ground truth, so the plan has none of its own. Stateless.
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
                .transformsFrom(RobotKeys.ODOMETRY.name(), RobotTopics.ODOM_FRAME, RobotTopics.BASE_FRAME);
        for (PlanarTransform t : RobotTopics.STATIC_TRANSFORMS) {
            plan.staticTransform(t.parent(), t.child(), t.xM(), t.yM(), t.yawRad());
        }
        return plan;
    }
}
