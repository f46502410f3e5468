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
 * <p>Run it with {@code java io.rtaware.examples.ThreeTaskController [file.mcap] [seconds]}.
 */
public final class ThreeTaskController {

    /** Where the wall stands, metres along x. */
    static final double WALL_X_M = 2.0;
    /** How far the pose source moves per cycle, metres. */
    static final double STEP_M = 0.01;

    private ThreeTaskController() {
    }

    /** Publishes a pose that advances along x by {@link #STEP_M} each cycle. One thread at a time. */
    static final class PoseSource implements Task {
        private Output<Odometry> pose;
        private long cycles;

        @Override
        public void initialize(TaskSetup setup) {
            pose = setup.produce(RobotKeys.ODOMETRY);
        }

        @Override
        public void execute(long nowNs) {
            pose.value().xM = STEP_M * cycles++;
            pose.publish();
        }
    }

    /**
     * Asks for a speed proportional to the distance left to the wall (0.5 m/s at most, 0 at the
     * wall), or none before the first pose. A function of its input only. One thread at a time.
     */
    static final class SlowBeforeWall implements Task {
        private Input<Odometry> pose;
        private Output<MotionRequest> request;

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
                double leftM = Math.max(0, WALL_X_M - pose.value().xM);
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

    /** @return a fresh set of the controller's three tasks */
    static List<TaskSpec> controller() {
        return List.of(
                new TaskSpec("pose", Schedule.periodic(Duration.ofMillis(10)), ErrorPolicy.CONTINUE, new PoseSource()),
                new TaskSpec("slow", Schedule.periodic(Duration.ofMillis(20)), ErrorPolicy.CONTINUE, new SlowBeforeWall()),
                new TaskSpec("drive", Schedule.periodic(Duration.ofMillis(50)), ErrorPolicy.CONTINUE, new Driver()));
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
        RunRecorder recorder = RecordingListener.attach(monitor, file, new RecordingPlan());

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
            ExactReplay.TaskResult r = ExactReplay.replay(recording, ThreeTaskController::controller, spec.name());
            replays.add(r);
            out.printf("replayed %-5s %d cycles: %d identical, %d different, %d not replayable%n",
                    r.name(), r.cycles(), r.identical(), r.different(), r.notReplayable());
        }
        return new Outcome(report, stats, replays);
    }

    /**
     * @param args optional: the MCAP file (default {@code three-tasks.mcap}) and the seconds to
     *     run (default 2)
     * @throws Exception if the run or the replay fails
     */
    public static void main(String[] args) throws Exception {
        Path file = Path.of(args.length > 0 ? args[0] : "three-tasks.mcap");
        Duration duration = Duration.ofMillis(Math.round(1000 * (args.length > 1 ? Double.parseDouble(args[1]) : 2.0)));
        run(file, duration, System.out, System.err);
    }
}
