package io.rtaware.app.run;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.TimeScaleConverter;
import io.rtaware.app.cli.TraceOptions;
import io.rtaware.app.live.LiveMixin;
import io.rtaware.app.ros2.ExportMixin;
import io.rtaware.app.ros2.Ros2RunMixin;
import java.io.IOException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.concurrent.Callable;
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
                "Default: the built-in simulator on a free loopback port, scenario paper-room, the paper's",
                "Set 4 periods (waypoint=100,obstacle=50,occupancy=100,planner=100 ms), time scale 1.",
                "The run ends at the finish, at the time limit, when the robot is stuck, or on Ctrl-C;",
                "in every case the robot is stopped first, then the summary is printed and written."})
public final class RunCommand implements Callable<Integer> {

    @Option(names = "--scenario", defaultValue = "paper-room", paramLabel = "paper-room|FILE",
            description = "Built-in scenario name or a scenario YAML file (default: ${DEFAULT-VALUE}).")
    String scenario;

    @Option(names = "--periods", paramLabel = "TASK=MS,...",
            description = "Task periods, e.g. waypoint=100,obstacle=50,occupancy=100,planner=100 (ms; tasks not named keep Set 4's).")
    String periods;

    @Option(names = "--time-scale", converter = TimeScaleConverter.class, defaultValue = "1", paramLabel = "K",
            description = "World time runs K times faster than wall time, emulating a computer K times slower (default: ${DEFAULT-VALUE}).")
    double timeScale;

    @Option(names = "--player", paramLabel = "HOST:PORT",
            description = "Use this Player server instead of the built-in simulator.")
    String player;

    @Option(names = "--seed", defaultValue = "1", description = "Seed of the simulator's sensor noise (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--out", paramLabel = "DIR", description = "Output folder (default: runs/<timestamp>).")
    Path out;

    @Option(names = "--quiet", description = "No live status line or miss reports.")
    boolean quiet;

    @Option(names = "--stuck-after", defaultValue = "60", paramLabel = "SECONDS",
            description = "World seconds without progress, while commanded to move, after which the robot is stuck (default: ${DEFAULT-VALUE}).")
    double stuckAfterS;

    @Option(names = "--grid-resolution", defaultValue = "0.05", paramLabel = "METRES",
            description = "Occupancy grid cell size (default: ${DEFAULT-VALUE}; the paper used 0.5).")
    double gridResolutionM;

    @Option(names = "--model", defaultValue = "r0",
            description = "Robot model name for ground truth through simulation:0 (default: ${DEFAULT-VALUE}).")
    String model;

    @Mixin
    TraceOptions trace;

    @Option(names = "--realtime",
            description = "SCHED_FIFO task threads in rate-monotonic order and 1 ns timer slack (Linux, root or CAP_SYS_NICE); one line and normal threads otherwise.")
    boolean realtime;

    @Mixin
    LiveMixin live;

    @Mixin
    Ros2RunMixin ros2;

    @Mixin
    ExportMixin export;

    @Override
    public Integer call() throws IOException {
        return new RobotRun(options(), ros2.options(), export.options(), System.out, System.err).execute();
    }

    RunOptions options() {
        if (!(stuckAfterS > 0)) {
            throw new UserError("--stuck-after must be positive, got " + stuckAfterS);
        }
        if (!(gridResolutionM > 0) || gridResolutionM > 2) {
            throw new UserError("--grid-resolution must be in (0, 2] metres, got " + gridResolutionM);
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
        return new RunOptions(scenario, taskPeriods, timeScale, host, port, seed, dir, quiet, stuckAfterS,
                gridResolutionM, model, trace, realtime, live.options());
    }
}
