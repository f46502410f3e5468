package io.rtaware.core.testing;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.MonitorListener;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Drives behaviors through the real monitor on a {@link ManualClock} and the step executor, with
 * scripted inputs: the task's inputs and outputs are the real handles, its data goes through the
 * real store, and every rule of a cycle holds (a cycle that throws commits nothing; only a
 * commit counts as a commit; stale runs, expired reads and errors are counted as in a run).
 *
 * <p>Two ways to drive, which can be mixed:
 * <ul>
 *   <li>by hand: tasks added with {@link Builder#task(String, Task)} are continuous and run only
 *   when the test says, {@link #cycle(String, long)} at a chosen world time;</li>
 *   <li>on their schedules: {@link #runUntil(long)} runs every task by its schedule, as a run
 *   would (tasks added with {@link Builder#task(String, Schedule, Task)}).</li>
 * </ul>
 * Inputs that no task under test produces are declared with {@link Builder#input(Key)} and
 * written by the test with {@link #publish(Key, StateValue, long)}: a scripted producer task
 * named {@code script:<key>} commits the value at that world time.
 *
 * <pre>{@code
 * TaskHarness h = TaskHarness.builder()
 *         .input(RobotKeys.LASER)
 *         .task("obstacle", new ObstacleAvoidanceTask(...))
 *         .build();
 * h.publish(RobotKeys.LASER, scan, ms(50));
 * h.cycle("obstacle", ms(100));
 * MotionRequest request = h.read(RobotKeys.MOTION_AVOID);
 * }</pre>
 *
 * <p>Not thread-safe: one test thread drives it. Time only moves forward.
 */
public final class TaskHarness {

    private static final String SCRIPT_PREFIX = "script:";

    private final ManualClock clock;
    private final Monitor monitor;
    private final StepExecutor step;
    private final Map<String, Scripted<?>> scripts;
    private final Map<String, Throwable> lastErrors;

    private TaskHarness(ManualClock clock, Monitor monitor, Map<String, Scripted<?>> scripts,
                        Map<String, Throwable> lastErrors) {
        this.clock = clock;
        this.monitor = monitor;
        this.scripts = scripts;
        this.lastErrors = lastErrors;
        this.step = monitor.startStepped();
    }

    /** @return a builder on a manual clock starting at world time 0 */
    public static Builder builder() {
        return new Builder(new ManualClock());
    }

    /**
     * @param clock the manual clock to run on (its current time is the start)
     * @return a builder
     */
    public static Builder builder(ManualClock clock) {
        return new Builder(Objects.requireNonNull(clock, "clock"));
    }

    /** @return the manual clock (tasks may advance it inside a cycle to simulate execution time) */
    public ManualClock clock() {
        return clock;
    }

    /** @return world time now */
    public long nowNs() {
        return clock.nanos();
    }

    /** @return the monitor under the harness (keys, producers, live counters, feeds) */
    public Monitor monitor() {
        return monitor;
    }

    /** @return the step executor, for tests that step release by release */
    public StepExecutor stepExecutor() {
        return step;
    }

    /**
     * Commits a value of a scripted input at world time {@code atNs}: advances the clock there and
     * runs the input's producer for one cycle, which publishes a copy of {@code value}.
     *
     * @param key a key declared with {@link Builder#input(Key)}
     * @param value the value (copied)
     * @param atNs world time of the commit, not before now
     * @param <T> the value type
     * @throws IllegalArgumentException if the key was not declared as a scripted input
     */
    public <T extends StateValue<T>> void publish(Key<T> key, T value, long atNs) {
        Scripted<?> script = scripts.get(key.name());
        if (script == null) {
            throw new IllegalArgumentException("'" + key.name() + "' is not a scripted input; declared: "
                    + scripts.keySet());
        }
        @SuppressWarnings("unchecked")
        Scripted<T> typed = (Scripted<T>) script;
        advanceTo(atNs);
        typed.pending = value;
        try {
            step.releaseNow(typed.taskName);
        } finally {
            typed.pending = null;
        }
    }

    /**
     * Runs one cycle of a task added with {@link Builder#task(String, Task)} at world time
     * {@code atNs}: copy-in of its inputs, its {@code execute}, then the commit of what it
     * published (or, if it threw, of nothing).
     *
     * @param task the task's name
     * @param atNs world time of the cycle's start, not before now
     * @return what the cycle threw, or null if it returned normally
     */
    public Throwable cycle(String task, long atNs) {
        advanceTo(atNs);
        lastErrors.remove(task);
        step.releaseNow(task);
        return lastErrors.remove(task);
    }

    /**
     * Runs every task by its schedule until {@code endNs} (releases before it), as a run would;
     * by-hand tasks are continuous and so run every idle step of the step executor.
     *
     * @param endNs world time to run until
     */
    public void runUntil(long endNs) {
        step.runUntil(endNs);
    }

    /**
     * @param key a key some task (or script) produces
     * @param <T> the value type
     * @return a copy of its newest committed value (the empty value if never committed)
     */
    public <T extends StateValue<T>> T read(Key<T> key) {
        T copy = key.newBuffer();
        monitor.read(key, copy);
        return copy;
    }

    /**
     * @param key a key some task (or script) produces
     * @return its generation: how many commits it has had
     */
    public long generation(Key<?> key) {
        return monitor.feed(key.name()).commits();
    }

    /**
     * @param task a task's name
     * @return its counters so far (releases, runs, errors, stale runs, ...)
     */
    public TaskCounters counters(String task) {
        return monitor.counters(task);
    }

    /**
     * Stops the monitor: {@code terminate()} on every task, then the report.
     *
     * @return the report, as a run writes it
     */
    public Report stop() {
        return monitor.stop();
    }

    private void advanceTo(long atNs) {
        if (atNs < clock.nanos()) {
            throw new IllegalArgumentException("world time " + atNs + " ns is before now (" + clock.nanos()
                    + " ns); time only moves forward");
        }
        clock.advanceTo(atNs);
    }

    /** The producer of a scripted input: publishes the value the test hands it, once per cycle. */
    private static final class Scripted<T extends StateValue<T>> implements Task {
        private final Key<T> key;
        /** Its task name, made once: publishing allocates nothing (replay feeds values through it per cycle). */
        final String taskName;
        private Output<T> out;
        T pending;

        Scripted(Key<T> key) {
            this.key = key;
            this.taskName = SCRIPT_PREFIX + key.name();
        }

        @Override
        public void initialize(TaskSetup setup) {
            out = setup.produce(key);
        }

        @Override
        public void execute(long nowNs) {
            if (pending != null) {
                out.value().copyFrom(pending);
                out.publish();
            }
        }
    }

    /** Declares the tasks and scripted inputs. Not thread-safe. */
    public static final class Builder {

        private final ManualClock clock;
        private final List<TaskSpec> specs = new ArrayList<>();
        private final Map<String, Scripted<?>> scripts = new LinkedHashMap<>();
        private final List<MonitorListener> listeners = new ArrayList<>();

        private Builder(ManualClock clock) {
            this.clock = clock;
        }

        /**
         * Declares an input the test writes with {@link TaskHarness#publish}.
         *
         * @param key the key
         * @return this builder
         */
        public Builder input(Key<?> key) {
            scripts.put(key.name(), scripted(key));
            return this;
        }

        private static <T extends StateValue<T>> Scripted<T> scripted(Key<T> key) {
            return new Scripted<>(key);
        }

        /**
         * Adds a task driven by hand ({@link TaskHarness#cycle}): continuous, error policy CONTINUE.
         *
         * @param name its name
         * @param task the behavior
         * @return this builder
         */
        public Builder task(String name, Task task) {
            return task(new TaskSpec(name, Schedule.continuous(), ErrorPolicy.CONTINUE, task));
        }

        /**
         * Adds a task that runs on its schedule ({@link TaskHarness#runUntil}).
         *
         * @param name its name
         * @param schedule when it runs
         * @param task the behavior
         * @return this builder
         */
        public Builder task(String name, Schedule schedule, Task task) {
            return task(new TaskSpec(name, schedule, ErrorPolicy.CONTINUE, task));
        }

        /**
         * @param spec a fully specified task
         * @return this builder
         */
        public Builder task(TaskSpec spec) {
            specs.add(Objects.requireNonNull(spec, "spec"));
            return this;
        }

        /**
         * @param listener receives the monitor's events
         * @return this builder
         */
        public Builder listener(MonitorListener listener) {
            listeners.add(Objects.requireNonNull(listener, "listener"));
            return this;
        }

        /**
         * Initializes every task (and script) and verifies the graph, as a run does, then starts
         * the step executor.
         *
         * @return the harness at the clock's current time
         * @throws io.rtaware.core.monitor.ConfigurationException as {@link Monitor.Builder#build()}
         */
        public TaskHarness build() {
            Map<String, Throwable> lastErrors = new ConcurrentHashMap<>();
            Monitor.Builder monitor = Monitor.builder(clock).listener(new MonitorListener() {
                @Override
                public void onTaskError(TaskInfo task, Throwable error, ErrorPolicy policy, long nowNs) {
                    lastErrors.put(task.name(), error);
                }
            });
            // Scripts first: at a tie in time, a scripted commit is visible to the tasks.
            scripts.forEach((key, script) -> monitor.task(script.taskName, Schedule.continuous(), script));
            specs.forEach(monitor::task);
            listeners.forEach(monitor::listener);
            return new TaskHarness(clock, monitor.build(), Map.copyOf(scripts), lastErrors);
        }
    }
}
