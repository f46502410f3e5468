package io.rtaware.bench;

import io.rtaware.bench.load.BenchSample;
import io.rtaware.bench.load.BenchTask;
import io.rtaware.bench.load.BusyWork;
import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The monitor's per-release bookkeeping, measured through the public step executor: one
 * {@link StepExecutor#step()} advances the manual clock to the next release and runs one cycle
 * (lateness and execution histograms, counters, deadline token, watchdog check on the clock
 * advance, listeners, input copy-in and output commit). The tasks do nothing else, so the time
 * per op is the framework's cost per release, without the thread wake-up (which the
 * {@code rtaware bench --compare} measures against a bare park loop).
 *
 * <p>Run: {@code java -jar rtaware-bench/target/benchmarks.jar MonitorBench}
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class MonitorBench {

    /** A task that does nothing: the cycle is pure bookkeeping. */
    static final class EmptyTask implements Task {
        @Override
        public void initialize(TaskSetup setup) {
            // Declares no data.
        }

        @Override
        public void execute(long nowNs) {
            // Nothing: the benchmark measures the monitor around it.
        }
    }

    /** Publishes a pose every cycle. */
    static final class PoseProducer implements Task {
        private Output<Odometry> out;

        @Override
        public void initialize(TaskSetup setup) {
            out = setup.produce(RobotKeys.ODOMETRY);
        }

        @Override
        public void execute(long nowNs) {
            out.value().xM += 1;
            out.publish();
        }
    }

    /** Reads the pose every cycle. */
    static final class PoseConsumer implements Task {
        private Input<Odometry> in;
        double sink;

        @Override
        public void initialize(TaskSetup setup) {
            in = setup.consume(RobotKeys.ODOMETRY);
        }

        @Override
        public void execute(long nowNs) {
            sink += in.value().xM;
        }
    }

    /** One periodic task without data. */
    @State(Scope.Thread)
    public static class Empty {
        Monitor monitor;
        StepExecutor step;

        /** Builds and starts the monitor on a manual clock. */
        @Setup(Level.Trial)
        public void start() {
            monitor = Monitor.builder(new ManualClock())
                    .task("empty", Schedule.periodic(1_000_000), new EmptyTask()).build();
            step = monitor.startStepped();
        }

        /** Terminates the monitor. */
        @TearDown(Level.Trial)
        public void stop() {
            monitor.stop();
        }
    }

    /** A producer and a consumer of a pose, both periodic at 1 kHz. */
    @State(Scope.Thread)
    public static class PosePair {
        Monitor monitor;
        StepExecutor step;

        /** Builds and starts the monitor on a manual clock. */
        @Setup(Level.Trial)
        public void start() {
            monitor = Monitor.builder(new ManualClock())
                    .task("odometry", Schedule.periodic(1_000_000), new PoseProducer())
                    .task("controller", Schedule.periodic(1_000_000), new PoseConsumer()).build();
            step = monitor.startStepped();
        }

        /** Terminates the monitor. */
        @TearDown(Level.Trial)
        public void stop() {
            monitor.stop();
        }
    }

    /**
     * Many periodic tasks released at one instant, as in the pool's in-phase drain (issue 36): each
     * step runs the next of them in slot order, so every release meets its task's state after the
     * other tasks' releases have pushed it out of the caches, as on the pool's workers. The time
     * per op is the bookkeeping of one release with the memory traffic of that many tasks, without
     * the pool's lock, heap hand-over and wake-ups.
     */
    @State(Scope.Thread)
    public static class InPhase {
        /** Tasks, all with a 10 ms period and released together. */
        @Param({"1000", "10000"})
        public int tasks;
        /**
         * Whether each task is one of {@code rtaware bench}'s with no work ({@link BenchTask}: it
         * publishes a value every cycle, a commit into the store under its write lock per
         * release) or does nothing.
         */
        @Param({"false", "true"})
        public boolean publishes;
        Monitor monitor;
        StepExecutor step;

        /** Builds and starts the monitor on a manual clock. */
        @Setup(Level.Trial)
        public void start() {
            Monitor.Builder builder = Monitor.builder(new ManualClock());
            BusyWork noWork = publishes ? BusyWork.calibrate() : null;
            for (int i = 0; i < tasks; i++) {
                String name = "t" + i;
                Task task = publishes ? new BenchTask(name, 0, null, noWork) : new EmptyTask();
                builder.task(name, Schedule.periodic(10_000_000), task);
            }
            monitor = builder.build();
            step = monitor.startStepped();
        }

        /** Terminates the monitor. */
        @TearDown(Level.Trial)
        public void stop() {
            monitor.stop();
        }
    }

    /**
     * @param s the monitor
     * @return whether a cycle ran (always true)
     */
    @Benchmark
    public boolean emptyTaskCycle(Empty s) {
        return s.step.step();
    }

    /**
     * One cycle of either task (they alternate): a commit or a copy-in of a pose plus bookkeeping.
     *
     * @param s the monitor
     * @return whether a cycle ran (always true)
     */
    @Benchmark
    public boolean poseProducerConsumerCycle(PosePair s) {
        return s.step.step();
    }

    /**
     * The same in-phase tasks without a framework, as a user's own loop would release them: for
     * each task in turn one clock read to see it is due, the task's code (the value
     * {@link BenchTask} publishes, here written and published with a release store of its
     * generation, so another thread that reads the generation first sees the value) and its next
     * release time. No lateness, execution time, deadline or statistics: the difference to
     * {@link #inPhaseRelease} is what rtaware's accounting of a release costs, over as many tasks.
     */
    @State(Scope.Thread)
    public static class HandWritten {
        /** Tasks, all with a 10 ms period and released together. */
        @Param({"1000", "10000"})
        public int tasks;
        HandTask[] all;
        int next;

        /** Builds the tasks, each with its own value, next to each other in memory. */
        @Setup(Level.Trial)
        public void start() {
            all = new HandTask[tasks];
            for (int i = 0; i < tasks; i++) {
                all[i] = new HandTask();
            }
        }
    }

    /** A task of {@link HandWritten}: its next release, its value and the value's generation. */
    static final class HandTask {
        private static final VarHandle GENERATION;

        static {
            try {
                GENERATION = MethodHandles.lookup().findVarHandle(HandTask.class, "generation", long.class);
            } catch (ReflectiveOperationException e) {
                throw new ExceptionInInitializerError(e);
            }
        }

        /** Its next release; every release is due in the loop, as in an in-phase drain that runs late. */
        long nextReleaseNs = Long.MIN_VALUE;
        long generation;
        final BenchSample value = new BenchSample();

        /** Runs the task's code and moves its release on by a period. */
        void release() {
            value.sequence++;
            GENERATION.setRelease(this, generation + 1);
            nextReleaseNs += 10_000_000;
        }
    }

    /**
     * One release of {@link HandWritten}'s loop: the next task in order.
     *
     * @param s the tasks
     * @return the released task's generation
     */
    @Benchmark
    public long handWrittenRelease(HandWritten s) {
        HandTask task = s.all[s.next];
        s.next = s.next + 1 == s.tasks ? 0 : s.next + 1;
        if (System.nanoTime() >= task.nextReleaseNs) {
            task.release();
        }
        return task.generation;
    }

    /**
     * One release of the in-phase drain: the next task in slot order, a full cycle of bookkeeping.
     *
     * @param s the monitor with its in-phase tasks
     * @return whether a cycle ran (always true)
     */
    @Benchmark
    public boolean inPhaseRelease(InPhase s) {
        return s.step.step();
    }
}
