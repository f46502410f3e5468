package io.rtaware.robotrun;

import io.rtaware.core.time.Clock;
import io.rtaware.core.time.Durations;
import io.rtaware.nav.Behavior;
import io.rtaware.nav.ControllerMetadata;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavKeys;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RobotRecordingPlan;
import io.rtaware.record.RunRecorder;
import io.rtaware.replay.ReplayableController;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.server.PlayerSimServer;
import java.util.Map;

/**
 * What a nav run records where: the robot's keys as {@link RobotRecordingPlan} puts them
 * ({@code /scan}, {@code /odom}, {@code /cmd_vel}, {@code /tf}, {@code /tf_static}), the true
 * pose on {@code /ground_truth} only when something knows it (the built-in simulator's or a
 * Player server's {@code simulation:0}; never the robot's own odometry; frame {@code world}), the
 * controller's map and plan on {@code /map} (latched) and {@code /plan} in {@code odom}, the frame
 * the controller builds and plans them in, and the run's settings as the file's
 * {@code rtaware.run} metadata, with the controller's configuration ({@link ControllerMetadata}:
 * what {@code rtaware replay} rebuilds the controller from). The robot is described as it was
 * ({@code robot}); its model is {@code robot_model} only for the built-in simulator, which
 * simulates that model: for another robot the controller's assumed model is
 * {@value #ASSUMED_ROBOT_MODEL}. Against the built-in simulator (over Player or ROS 2), whose clock is the
 * run's, scans and odometry are stamped when the simulator measured them; against another robot,
 * when they were committed. {@code /clock} is recorded when the world runs on simulated time: the
 * simulator, or a time scale other than 1. Stateless.
 */
final class NavRecording {

    /** Metadata entry naming the model whose parameters the controller assumed for a robot not simulated here. */
    static final String ASSUMED_ROBOT_MODEL = "assumed_robot_model";

    private NavRecording() {
    }

    /**
     * @param scenario the scenario
     * @param settings the run's settings
     * @param navConfig the controller's configuration (recorded whole, for replay)
     * @param modelName the robot model's name
     * @param robot where the robot is, in words
     * @param simulator the built-in simulator, stepping on the run's clock, or null for another robot
     * @param groundTruth whether something knows the true pose (then it is recorded)
     * @return the plan
     */
    static RecordingPlan plan(Scenario scenario, NavRun.Settings settings, NavConfig navConfig, String modelName,
                              String robot, PlayerSimServer simulator, boolean groundTruth) {
        StringBuilder periods = new StringBuilder();
        for (Behavior b : Behavior.values()) {
            periods.append(periods.length() == 0 ? "" : ",").append(b.taskName()).append('=')
                    .append(Durations.format(navConfig.periods().ns(b)));
        }
        RecordingPlan plan = RobotRecordingPlan.create()
                .topic(NavKeys.MAP, RobotTopics.MAP, RobotTopics.ODOM_FRAME)
                .latched(NavKeys.MAP)
                .topic(NavKeys.PATH, RobotTopics.PLAN, RobotTopics.ODOM_FRAME)
                .metadata("scenario", scenario.name())
                .metadata("periods", periods.toString())
                .metadata("time_scale", Double.toString(settings.timeScale()))
                .metadata("seed", Long.toString(settings.seed()))
                .metadata("grid_resolution_m", Double.toString(settings.gridResolutionM()))
                .metadata("robot", robot);
        Map<String, String> controller = ControllerMetadata.entries(navConfig, modelName,
                Runtime.getRuntime().availableProcessors());
        if (simulator == null) { // the model is the controller's assumption, not the robot's
            controller.put(ASSUMED_ROBOT_MODEL, controller.remove(ControllerMetadata.ROBOT_MODEL));
        }
        controller.forEach(plan::metadata);
        if (groundTruth) {
            plan.withGroundTruth();
        }
        ReplayableController.describe(plan, NavReplayProvider.ID, ControllerMetadata.configuration(navConfig));
        if (simulator != null) {
            plan.robotClockOriginNs(simulator.clockOriginNs()); // the simulator's timestamps are the run's clock
        }
        if (simulator != null || settings.timeScale() != 1.0) {
            plan.clock(RecordingPlan.CLOCK_PERIOD_NS);
        }
        return plan;
    }

    /**
     * Records every pose the referee samples as {@code geometry_msgs/msg/PoseStamped}.
     *
     * @param source the referee's pose source
     * @param recorder the recorder, or null (then {@code source} itself is returned)
     * @param clock world clock
     * @return a source that records what it returns
     */
    static Referee.PoseSource recordingGroundTruth(Referee.PoseSource source, RunRecorder recorder, Clock clock) {
        if (recorder == null) {
            return source;
        }
        return new Referee.PoseSource() {
            @Override
            public Pose2d pose() throws Exception {
                Pose2d pose = source.pose();
                if (pose != null) {
                    recorder.groundTruth(clock.nanos(), pose.xM(), pose.yM(), pose.yawRad());
                }
                return pose;
            }

            @Override
            public String kind() {
                return source.kind();
            }

            @Override
            public void close() throws Exception {
                source.close();
            }
        };
    }
}
