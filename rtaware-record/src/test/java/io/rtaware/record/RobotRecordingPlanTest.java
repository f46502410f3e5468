package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.value.PlanarTransform;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The robot's plan puts its keys on the topics and frames of {@link RobotTopics}, in one place. */
class RobotRecordingPlanTest {

    @Test
    void theRobotsKeysGoOnTheRos2TopicsInRep105Frames() {
        RecordingPlan plan = RobotRecordingPlan.create();

        assertEquals("/scan", plan.topicOf(RobotKeys.LASER.name()));
        assertEquals("laser", plan.frameOf(RobotKeys.LASER.name()));
        assertEquals("/odom", plan.topicOf(RobotKeys.ODOMETRY.name()));
        assertEquals("odom", plan.frameOf(RobotKeys.ODOMETRY.name()));
        assertArrayEquals(new String[] {"odom", "base_link"}, plan.transformsOf(RobotKeys.ODOMETRY.name()));
        assertEquals("/cmd_vel", plan.topicOf(RobotKeys.MOTOR.name()));
        assertFalse(plan.hasGroundTruth(), "a robot's odometry is not its true pose: the caller declares a truth source");
        assertEquals(List.of(new PlanarTransform("base_link", "laser", 0, 0, 0)), plan.staticTransforms(),
                "no map -> odom: nothing localizes, and world truth is not odometry's frame");
        assertEquals(RecordingPlan.DATA_PREFIX + "course", plan.topicOf("course"), "another key keeps its own topic");
    }

    @Test
    void eachCallIsANewPlanToAddAControllersTopicsTo() {
        RecordingPlan one = RobotRecordingPlan.create().topic("map", RobotTopics.MAP, RobotTopics.ODOM_FRAME);

        assertEquals("/map", one.topicOf("map"));
        assertEquals(RecordingPlan.DATA_PREFIX + "map", RobotRecordingPlan.create().topicOf("map"));
    }
}
