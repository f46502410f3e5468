package io.rtaware.app.run;

import io.rtaware.nav.ControllerMetadata;
import io.rtaware.core.time.Clock;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavKeys;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RobotRecordingPlan;
import io.rtaware.record.RunRecorder;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.server.PlayerSimServer;
import java.util.Locale;

/**
 * What {@code run --record} records where: the robot's keys on the topics ROS 2 tools expect
 * ({@code /scan}, {@code /odom}, {@code /cmd_vel}, {@code /map}, {@code /plan}), the ground truth
 * on {@code /ground_truth}, the REP 105 frames on {@code /tf_static} ({@code map} to {@code odom},
 * {@code base_link} to {@code laser}) and {@code /tf} ({@code odom} to {@code base_link} from
 * odometry, {@code map} to {@code ground_truth}), and the run's settings as the file's {@code rtaware.run} metadata
 * (what {@code rtaware replay} rebuilds the controller from). Against the built-in simulator
 * (over Player or ROS 2), whose clock is the run's, scans and odometry are stamped when the
 * simulator measured them; against another robot, when they were committed. {@code /clock} is
 * recorded when the world runs on simulated time: the simulator, or a time scale other than 1.
 */
final class RunRecording {

    /** Metadata: the command that recorded the file. */
    static final String COMMAND = "command";

    private RunRecording() {
    }

    /**
     * @param scenario the scenario
     * @param options the run's options
     * @param navConfig the controller's configuration (recorded whole, for replay)
     * @param modelName the robot model's name
     * @param simulator the built-in simulator, stepping on the run's clock, or null for another robot
     * @return the plan
     */
    static RecordingPlan plan(Scenario scenario, RunOptions options, NavConfig navConfig, String modelName,
                              PlayerSimServer simulator) {
        RecordingPlan plan = RobotRecordingPlan.create()
                .topic(NavKeys.MAP, RobotTopics.MAP, RobotTopics.MAP_FRAME)
                .latched(NavKeys.MAP)
                .topic(NavKeys.PATH, RobotTopics.PLAN, RobotTopics.MAP_FRAME)
                .metadata(COMMAND, "run")
                .metadata("scenario", scenario.name())
                .metadata("periods", options.periods().toString())
                .metadata("time_scale", Double.toString(options.timeScale()))
                .metadata("seed", Long.toString(options.seed()))
                .metadata("grid_resolution_m", Double.toString(options.gridResolutionM()))
                .metadata("robot", options.builtInSimulator() ? "built-in simulator"
                        : String.format(Locale.ROOT, "player %s:%d", options.playerHost(), options.playerPort()));
        ControllerMetadata.entries(navConfig, modelName, Runtime.getRuntime().availableProcessors())
                .forEach(plan::metadata);
        if (simulator != null) {
            plan.robotClockOriginNs(simulator.clockOriginNs()); // the simulator's timestamps are the run's clock
        }
        if (simulator != null || options.timeScale() != 1.0) {
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
