package io.rtaware.examples;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.MonotonicSleeper;
import io.rtaware.core.time.SystemClock;
import io.rtaware.record.RecordingListener;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RecordingStats;
import io.rtaware.record.RunRecorder;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.replay.ExactReplay;
import io.rtaware.replay.Recording;
import io.rtaware.replay.ReplayableController;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.rt.ClockNanosleep;
import io.rtaware.rt.RealtimeThreads;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * A controller of three tasks that embeds the monitor the way a robot developer would, with no
 * command line: a pose source every 10 ms, a task that slows down before a wall every 20 ms, and
 * a driver that turns the request into a motor command every 50 ms. It asks for real-time
 * threads ({@code rtaware-rt}: SCHED_FIFO where permitted, one line and normal threads where
 * not), records the run to MCAP ({@code rtaware-record}), then replays every task's recorded
 * cycles exactly ({@code rtaware-replay}) and prints whether each one computed the same outputs
 * again.
 *
 * <p>The recording names this class as its replay provider ({@link ReplayableController}, registered
 * in {@code META-INF/services}) with the controller's configuration (the wall, the step), so
 * {@code rtaware replay FILE.mcap --classpath CLASSES} re-executes it exactly, or with other
 * periods ({@code --periods slow=40ms}).
 *
 * <p>Run it with {@code java io.rtaware.examples.ThreeTaskController FILE.mcap [seconds]}.
 */
public final class ThreeTaskController implements ReplayableController {

    /** The id the recordings name this controller's replay provider by. */
    public static final String ID = "io.rtaware.examples.three-tasks";
    /** Where the wall stands, metres along x. */
    static final double WALL_X_M = 2.0;
    /** How far the pose source moves per cycle, metres. */
    static final double STEP_M = 0.01;
    /** The tasks' periods as run, ms, in the controller's order. */
    private static final Map<String, Long> PERIODS_MS = Map.of("pose", 10L, "slow", 20L, "drive", 50L);

    /** Creates the replay provider (for {@link java.util.ServiceLoader}); the controller itself is static. */
    public ThreeTaskController() {
    }

    /** Publishes a pose that advances along x by a step each cycle. One thread at a time. */
    static final class PoseSource implements Task {
        private final double stepM;
        private Output<Odometry> pose;
        private long cycles;

        PoseSource(double stepM) {
            this.stepM = stepM;
        }

        @Override
        public void initialize(TaskSetup setup) {
            pose = setup.produce(RobotKeys.ODOMETRY);
        }

        @Override
        public void execute(long nowNs) {
            pose.value().xM = stepM * cycles++;
            pose.publish();
        }
    }

    /**
     * Asks for a speed proportional to the distance left to the wall (0.5 m/s at most, 0 at the
     * wall), or none before the first pose. A function of its input only. One thread at a time.
     */
    static final class SlowBeforeWall implements Task {
        private final double wallXM;
        private Input<Odometry> pose;
        private Output<MotionRequest> request;

        SlowBeforeWall(double wallXM) {
            this.wallXM = wallXM;
        }

        @Override
        public void initialize(TaskSetup setup) {
            pose = setup.consume(RobotKeys.ODOMETRY);
            request = setup.produce(RobotKeys.MOTION_AVOID);
        }

        @Override
        public void execute(long nowNs) {
            if (!pose.hasValue()) {
                request.value().release();
            } else {
                double leftM = Math.max(0, wallXM - pose.value().xM);
                request.value().request(Math.min(0.5, 0.5 * leftM), 0);
            }
            request.publish();
        }
    }

    /** Sends the requested speed to the motors, or stop without a request. One thread at a time. */
    static final class Driver implements Task {
        private Input<MotionRequest> request;
        private Output<VelocityCommand> motor;

        @Override
        public void initialize(TaskSetup setup) {
            request = setup.consume(RobotKeys.MOTION_AVOID);
            motor = setup.produce(RobotKeys.MOTOR);
        }

        @Override
        public void execute(long nowNs) {
            MotionRequest r = request.value();
            if (request.hasValue() && r.active) {
                motor.value().set(r.vxMps, r.omegaRadPerSec);
            } else {
                motor.value().set(0, 0);
            }
            motor.publish();
        }
    }

    /** @return a fresh set of the controller's three tasks, as it runs */
    static List<TaskSpec> controller() {
        return controller(WALL_X_M, STEP_M, Map.of());
    }

    private static List<TaskSpec> controller(double wallXM, double stepM, Map<String, Long> periodsNs) {
        for (String name : periodsNs.keySet()) {
            if (!PERIODS_MS.containsKey(name)) {
                throw new IllegalArgumentException("unknown task '" + name + "'; tasks: pose, slow, drive");
            }
        }
        return List.of(
                new TaskSpec("pose", schedule("pose", periodsNs), ErrorPolicy.CONTINUE, new PoseSource(stepM)),
                new TaskSpec("slow", schedule("slow", periodsNs), ErrorPolicy.CONTINUE, new SlowBeforeWall(wallXM)),
                new TaskSpec("drive", schedule("drive", periodsNs), ErrorPolicy.CONTINUE, new Driver()));
    }

    private static Schedule schedule(String task, Map<String, Long> periodsNs) {
        return Schedule.periodic(Duration.ofNanos(periodsNs.getOrDefault(task, PERIODS_MS.get(task) * 1_000_000L)));
    }

    /** @return {@value #ID} */
    @Override
    public String id() {
        return ID;
    }

    /**
     * @param configuration {@code wall_x_m} and {@code step_m}, as {@link #run} records them
     * @param periodsNs period in ns of each task to change ({@code pose}, {@code slow}, {@code drive})
     * @return a fresh set of the controller's tasks
     * @throws IllegalArgumentException if an entry is missing or not a number, or a task is unknown
     */
    @Override
    public List<TaskSpec> tasks(Map<String, String> configuration, Map<String, Long> periodsNs) {
        return controller(number(configuration, "wall_x_m"), number(configuration, "step_m"), periodsNs);
    }

    private static double number(Map<String, String> configuration, String name) {
        String value = configuration.get(name);
        if (value == null) {
            throw new IllegalArgumentException("the controller's configuration has no " + name);
        }
        try {
            return Double.parseDouble(value);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("the controller's " + name + " is not a number: '" + value + "'");
        }
    }

    /** @return what {@link #tasks} rebuilds the controller from, as the recording stores it */
    static Map<String, String> configuration() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("wall_x_m", Double.toString(WALL_X_M));
        m.put("step_m", Double.toString(STEP_M));
        return m;
    }

    /**
     * What one run gave.
     *
     * @param report the monitor's report
     * @param recording what the recorder wrote and dropped
     * @param replays the exact replay of each task, in registration order
     */
    record Outcome(Report report, RecordingStats recording, List<ExactReplay.TaskResult> replays) {
    }

    /**
     * Runs the controller on real-time threads for a while, recording it, then replays it.
     *
     * @param file the MCAP file to write
     * @param duration how long to run
     * @param out where the summary goes
     * @param err where the one line about real-time threads goes, if they are not available
     * @return what the run gave
     * @throws IOException if the recording cannot be written or read back
     * @throws InterruptedException if interrupted while the controller runs
     */
    static Outcome run(Path file, Duration duration, PrintStream out, PrintStream err)
            throws IOException, InterruptedException {
        Monitor.Builder builder = Monitor.builder(new SystemClock());
        RealtimeThreads rt = RealtimeThreads.configure(RealtimeThreads.DEFAULT_TOP_PRIORITY, Map.of(), err);
        if (rt != null) {
            builder.threadSetup(rt);
        }
        Optional<MonotonicSleeper> sleeper = ClockNanosleep.load();
        sleeper.ifPresent(builder::sleeper);
        controller().forEach(builder::task);
        Monitor monitor = builder.build();
        RecordingPlan plan = ReplayableController.describe(new RecordingPlan(), ID, configuration());
        RunRecorder recorder = RecordingListener.attach(monitor, file, plan);

        monitor.start();
        Thread.sleep(duration.toMillis());
        Report report = monitor.stop();
        RecordingStats stats = recorder.finish();

        out.printf("ran %.1f s on %s threads, %s sleeps%n", report.durationS(),
                rt != null && rt.fifo() ? "SCHED_FIFO" : "normal", sleeper.isPresent() ? "clock_nanosleep" : "parked");
        for (TaskSpec spec : controller()) {
            TaskReport t = report.task(spec.name());
            out.printf("  %-5s releases %d, runs %d, misses %d%n", t.name(), t.releases(), t.runs(), t.misses());
        }
        Recording recording = Recording.load(McapReader.open(file), file);
        List<ExactReplay.TaskResult> replays = new ArrayList<>();
        for (TaskSpec spec : controller()) {
            ExactReplay.TaskResult r = ExactReplay.replay(recording,
                    () -> new ThreeTaskController().tasks(configuration(), Map.of()), spec.name());
            replays.add(r);
            out.printf("replayed %-5s %d cycles: %d identical, %d different, %d not replayable%n",
                    r.name(), r.cycles(), r.identical(), r.different(), r.notReplayable());
        }
        return new Outcome(report, stats, replays);
    }

    /**
     * Runs, records to the file and replays in-process; {@code rtaware replay FILE.mcap --classpath}
     * this module's classes replays the file again.
     *
     * @param args the MCAP file to write, and optionally the seconds to run (default 2)
     * @throws Exception if the run or the replay fails
     */
    public static void main(String[] args) throws Exception {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: ThreeTaskController FILE.mcap [SECONDS]");
            System.exit(2);
        }
        Path file = Path.of(args[0]);
        Duration duration = Duration.ofMillis(Math.round(1000 * (args.length > 1 ? Double.parseDouble(args[1]) : 2.0)));
        run(file, duration, System.out, System.err);
    }
}
