package io.rtaware.app.run;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.DurationConverter;
import io.rtaware.app.cli.MemoryBudget;
import io.rtaware.app.cli.RecordOptions;
import io.rtaware.app.cli.TimeScaleConverter;
import io.rtaware.app.cli.TraceOptions;
import io.rtaware.app.foxglove.FoxgloveMixin;
import io.rtaware.app.live.LiveMixin;
import io.rtaware.app.output.OutputFolder;
import io.rtaware.app.ros2.DdsMixin;
import io.rtaware.app.ros2.ExportMixin;
import io.rtaware.app.ros2.Ros2RunMixin;
import io.rtaware.app.ros2.RosDistroMixin;
import io.rtaware.core.conditions.CpuQuota;
import io.rtaware.core.time.Durations;
import io.rtaware.experiment.ExperimentRunner;
import io.rtaware.ros2.graph.DdsSettings;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.world.RobotModel;
import java.io.IOException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code rtaware run}: the product's main job. Drives the paper's waypoint course with the four
 * behaviors and the position mediator, in the built-in simulator (reached over TCP like any
 * Player server) or on an external Player server, and writes the run's report.
 */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = {"Run the paper's waypoint-navigation controller and report its timing.",
                "Default: the built-in simulator on a free loopback port, scenario paper-room, the paper's Set 4 "
                + "periods (waypoint=100ms,obstacle=50ms,occupancy=100ms,planner=100ms), time scale 1.",
                "The run ends at the finish, at the time limit, when the robot is stuck, or on Ctrl-C; in every case "
                + "the robot is stopped first, then the summary is printed and written."})
public final class RunCommand implements Callable<Integer> {

    @Option(names = "--scenario", defaultValue = ScenarioLoader.PAPER_ROOM, paramLabel = "NAME|FILE",
            description = "A built-in scenario (" + ScenarioLoader.BUILT_IN_NAMES + ") or a scenario YAML file (default: ${DEFAULT-VALUE}).")
    String scenario;

    @Option(names = "--periods", paramLabel = "TASK=DURATION,...",
            description = "Task periods, e.g. waypoint=100ms,obstacle=50ms,occupancy=100ms,planner=100ms (tasks not named keep Set 4's).")
    String periods;

    @Option(names = "--time-scale", converter = TimeScaleConverter.class, defaultValue = "1", paramLabel = "K",
            description = "World time runs K times faster than wall time, emulating a computer K times slower (default: ${DEFAULT-VALUE}).")
    double timeScale;

    @Option(names = "--player", paramLabel = "HOST:PORT",
            description = "Use this Player server instead of the built-in simulator.")
    String player;

    @Option(names = "--seed", defaultValue = "1", paramLabel = "S", description = "Seed of this run's noise: laser ranges, odometry increments (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--robot-seed", defaultValue = "4", paramLabel = "S",
            description = "Seed of the simulated robot's systematic odometry errors (scale, heading, drift), drawn once "
                    + "per robot: the same robot seed is the same robot in every run, as the paper used one Koala "
                    + "(default: ${DEFAULT-VALUE}).")
    long robotSeed;

    @Option(names = "--out", paramLabel = "DIR", description = "Output folder (default: runs/<timestamp>).")
    Path out;

    @Option(names = "--quiet", description = "No live status line or miss reports.")
    boolean quiet;

    @Option(names = "--stuck-after", defaultValue = "60s", paramLabel = "DURATION", converter = DurationConverter.class,
            description = "World time without progress, while commanded to move, after which the robot is stuck (default: ${DEFAULT-VALUE}).")
    long stuckAfterNs;

    @Option(names = "--grid-resolution", defaultValue = "0.05", paramLabel = "METRES",
            description = "Occupancy grid cell size (default: ${DEFAULT-VALUE}; the paper used 0.5).")
    double gridResolutionM;

    @Option(names = "--model", defaultValue = "r0", paramLabel = "NAME",
            description = "Robot model name for ground truth through simulation:0 (default: ${DEFAULT-VALUE}).")
    String model;

    @Option(names = "--inflation-margin", defaultValue = "0", paramLabel = "METRES",
            description = "Clearance the path planner adds to the robot's radius when it inflates obstacles (default: "
                    + "${DEFAULT-VALUE}: the planner keeps the body clear, the obstacle avoider keeps the margin; 0.05 is "
                    + "the controller's library default and earlier versions' run default, under which the avoider's "
                    + "zone never sees an obstacle).")
    double inflationMarginM;

    @Option(names = "--robot", paramLabel = "koala|ideal",
            description = "Robot model of the built-in simulator: koala (odometry drift, acceleration limits, command latency, URG laser timing) or ideal (the exact point robot of earlier versions); default: the scenario's, else koala.")
    String robot;

    @Option(names = "--top-speed", paramLabel = "M/S",
            description = "The controller's top speed in m/s, up to the Koala's 0.6 (default: the scenario's, else the paper's 0.1).")
    Double topSpeedMps;

    @Mixin
    TraceOptions trace;

    @Mixin
    RecordOptions record;

    @Option(names = "--realtime",
            description = "SCHED_FIFO task threads in rate-monotonic order, 1 ns timer slack, and the CPUs held out of "
                    + "deep idle for the run through /dev/cpu_dma_latency (Linux, root or CAP_SYS_NICE); one line and "
                    + "normal threads otherwise.")
    boolean realtime;

    @Option(names = "--kernel-timer-slack",
            description = "Leave the task threads the kernel's timer slack (50 us by default on Linux) instead of "
                    + "asking for 1 ns, to compare; the slack they had is in the report's conditions (timer_slack_ns).")
    boolean kernelTimerSlack;

    @Option(names = "--cpu-limit", paramLabel = "CPUS", description = "Run under a CPU quota (e.g. 0.5): this JVM, with "
            + "the controller and the built-in server, in a cgroup of its own (the CPU controller of cgroup v2 or v1; needs "
            + "root), removed at exit; the report's conditions give it as cgroup_quota_cpus.")
    Double cpuLimit;

    @Mixin
    LiveMixin live;

    @Mixin
    FoxgloveMixin foxglove;

    @Mixin
    Ros2RunMixin ros2;

    @Mixin
    ExportMixin export;

    @Mixin
    RosDistroMixin rosDistro;

    @Mixin
    DdsMixin dds;

    private final Supplier<MemoryBudget> memory;

    /** The command with this JVM's heap as its memory budget. */
    public RunCommand() {
        this(MemoryBudget::ofThisJvm);
    }

    /** @param memory the heap the trace may take, asked for when the command runs */
    public RunCommand(Supplier<MemoryBudget> memory) {
        this.memory = memory;
    }

    @Override
    public Integer call() throws IOException {
        RunOptions options = options();
        foxglove.address(); // a bad --foxglove ends the command before anything runs
        ExperimentParentWatch.start(System.getenv(ExperimentRunner.PARENT_PID_ENV), System.err, System::exit);
        try (CpuQuota quota = cpuLimit == null ? null : CpuQuota.confineThisProcess(cpuLimit)) {
            return execute(options);
        } catch (CpuQuota.Unavailable e) {
            throw new UserError(e.getMessage());
        }
    }

    /** Runs after this process is under its CPU quota, if any: nothing before it measures or starts a server. */
    private int execute(RunOptions options) throws IOException {
        memory.get().require(trace.heapBytes(), trace.describe());
        Ros2Distro distro = rosDistro.distro(ros2.requested() || export.requested(), "--ros2 or --export");
        Optional<DdsSettings> ddsSettings = dds.settings(ros2.requested() || export.requested(), "--ros2 or --export",
                ros2.domain(), distro);
        return new RobotRun(options, ros2.options(distro, ddsSettings), export.options(distro, ddsSettings), System.out,
                System.err).recording(record)
                .foxglove(foxglove).execute();
    }

    RunOptions options() {
        if (stuckAfterNs <= 0) {
            throw new UserError("--stuck-after must be positive, got " + Durations.format(stuckAfterNs));
        }
        if (!(gridResolutionM > 0) || gridResolutionM > 2) {
            throw new UserError("--grid-resolution must be in (0, 2] metres, got " + gridResolutionM);
        }
        if (!(inflationMarginM >= 0) || inflationMarginM > 1) {
            throw new UserError("--inflation-margin must be in [0, 1] metres, got " + inflationMarginM);
        }
        if (robot != null && !robot.equals(RobotModel.KOALA_NAME) && !robot.equals(RobotModel.IDEAL_NAME)) {
            throw new UserError("--robot must be koala or ideal, got '" + robot + "'");
        }
        if (topSpeedMps != null && !(topSpeedMps > 0 && topSpeedMps <= RobotModel.KOALA_MAX_SPEED_MPS)) {
            throw new UserError("--top-speed must be in (0, " + RobotModel.KOALA_MAX_SPEED_MPS
                    + "] m/s (the Koala's maximum), got " + topSpeedMps);
        }
        TaskPeriods taskPeriods = periods == null ? TaskPeriods.paperSet4()
                : TaskPeriods.parse(periods, TaskPeriods.paperSet4());
        String host = null;
        int port = 0;
        if (player != null) {
            int colon = player.lastIndexOf(':');
            if (colon <= 0 || colon == player.length() - 1) {
                throw new UserError("--player expects HOST:PORT (e.g. 127.0.0.1:6665), got '" + player + "'");
            }
            host = player.substring(0, colon);
            try {
                port = Integer.parseInt(player.substring(colon + 1));
            } catch (NumberFormatException e) {
                port = -1;
            }
            if (port < 1 || port > 65535) {
                throw new UserError("--player port must be 1..65535, got '" + player.substring(colon + 1) + "'");
            }
        }
        Path dir = out != null ? out
                : Path.of("runs", LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")));
        OutputFolder.of("--out", dir);
        trace.checkOutput();
        record.checkOutput();
        return new RunOptions(scenario, taskPeriods, timeScale, host, port, seed, dir, quiet, stuckAfterNs / 1e9,
                gridResolutionM, model, trace, realtime, kernelTimerSlack, live.options(), robot, topSpeedMps,
                inflationMarginM, robotSeed);
    }
}
