package io.rtaware.core.monitor;

import io.rtaware.core.data.FeedStats;
import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.data.StateVariable;
import io.rtaware.core.report.DataReport;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import io.rtaware.core.time.Durations;
import io.rtaware.core.time.ManualClock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.stream.Collectors;

/**
 * Runs a set of tasks at their declared rates and watches them: the paper's MONITOR.
 *
 * <p>{@link Builder#build()} performs the Initialization state for every task (declarations,
 * allocation) and verifies the whole data graph, throwing one {@link ConfigurationException}
 * that lists every violation. {@link #start()} runs the tasks on one named platform thread
 * each, plus a watchdog thread that reports deadline misses at the deadline;
 * {@link #startStepped()} runs them instead on a {@link StepExecutor} for exact tests.
 * {@link #stop()} is the Termination state: tasks stop, {@code terminate()} is called on each,
 * and the {@link Report} is built and handed to the termination handlers.
 *
 * <p>Thread-safe: {@code stop()} may be called from any thread, any number of times.
 */
public final class Monitor {

    private enum Phase { READY, RUNNING, TERMINATED }

    private final Clock clock;
    private final List<TaskRuntime> runtimes;
    private final List<StateVariable<?>> variables;
    private final Map<String, String> producers;
    private final Map<String, List<String>> consumers;
    private final List<String> keyNames;
    private final Map<String, StateVariable<?>> variablesByName;
    private final List<Consumer<Report>> terminationHandlers = new CopyOnWriteArrayList<>();
    private final List<MonitorListener> listeners;
    private final ThreadSetup threadSetup;
    private final ListenerFanOut events;
    private final FrameworkFaults faults;
    private final CountDownLatch terminated = new CountDownLatch(1);
    private final Object lifecycle = new Object();
    private Phase phase = Phase.READY;
    private Executor executor;
    private long startNs;
    private long stopNs;
    private volatile Report report;
    /** Set once every task thread has returned: their own state may then be read. */
    private volatile boolean tasksStopped;

    private Monitor(Clock clock, List<TaskRuntime> runtimes, List<StateVariable<?>> variables,
                    Map<String, String> producers, Map<String, List<String>> consumers,
                    List<MonitorListener> listeners, ThreadSetup threadSetup, ListenerFanOut events,
                    FrameworkFaults faults) {
        this.clock = clock;
        this.events = events;
        this.faults = faults;
        this.threadSetup = threadSetup;
        this.listeners = new ArrayList<>(listeners);
        this.runtimes = runtimes;
        this.variables = variables;
        this.producers = producers;
        this.consumers = consumers;
        this.keyNames = variables.stream().map(v -> v.key().name()).toList();
        Map<String, StateVariable<?>> byName = new LinkedHashMap<>();
        variables.forEach(v -> byName.put(v.key().name(), v));
        this.variablesByName = Map.copyOf(byName);
    }

    /**
     * @param clock the world clock every task and measurement uses
     * @return a builder
     */
    public static Builder builder(Clock clock) {
        return new Builder(clock);
    }

    /** @return the world clock */
    public Clock clock() {
        return clock;
    }

    /** @return the tasks in registration order */
    public List<TaskInfo> tasks() {
        return Collections.unmodifiableList(runtimes);
    }

    /**
     * @return key names by key index (see {@link MonitorListener#onCommit}), in the order the
     *     producing tasks declared them
     */
    public List<String> keyNames() {
        return keyNames;
    }

    /**
     * @return the keys by key index (see {@link MonitorListener#onCommitValue}), in the order
     *     of {@link #keyNames()}
     */
    public List<Key<?>> keys() {
        return variables.stream().<Key<?>>map(StateVariable::key).toList();
    }

    /**
     * @param task a task's name
     * @return its live counters
     * @throws IllegalArgumentException naming the task and the known tasks if there is none
     */
    public TaskCounters counters(String task) {
        return runtime(task).counters();
    }

    /**
     * @param index a task's index
     * @return its live counters
     */
    public TaskCounters counters(int index) {
        return runtimes.get(index).counters();
    }

    /**
     * @param key a key's name
     * @return its live feed statistics
     */
    public FeedStats feed(String key) {
        return variable(key).feedStats();
    }

    private StateVariable<?> variable(String key) {
        StateVariable<?> variable = variablesByName.get(key);
        if (variable == null) {
            throw new IllegalArgumentException("no key '" + key + "'; keys: " + keyNames);
        }
        return variable;
    }

    /**
     * Reads a key's newest value from outside the task set, for observers such as a run
     * supervisor or a live view: copies it into {@code target} under the key's read lock, like a
     * consumer's copy-in, without being a task (so it appears in no report). Any thread.
     *
     * @param key the key
     * @param target receives the value
     * @param <T> the value type
     * @return the generation copied (0 if never written: {@code target} then holds the empty value)
     * @throws IllegalArgumentException if no task produces the key or its type differs
     */
    public <T extends StateValue<T>> long read(Key<T> key, T target) {
        StateVariable<?> variable = variable(key.name());
        if (!variable.key().type().equals(key.type())) {
            throw new IllegalArgumentException("key '" + key.name() + "' holds " + variable.key().type().getSimpleName()
                    + ", not " + key.type().getSimpleName());
        }
        @SuppressWarnings("unchecked")
        StateVariable<T> typed = (StateVariable<T>) variable;
        StateVariable.ReadCursor cursor = new StateVariable.ReadCursor();
        typed.copyTo(target, -1, cursor);
        return cursor.generation();
    }

    /**
     * @param key a key's name
     * @return the name of the task that produces it
     * @throws IllegalArgumentException if no task produces it
     */
    public String producer(String key) {
        variable(key);
        return producers.get(key);
    }

    /**
     * @param key a key's name
     * @return the names of the tasks that consume it, empty if none
     * @throws IllegalArgumentException if no task produces it
     */
    public List<String> consumers(String key) {
        producer(key);
        return List.copyOf(consumers.getOrDefault(key, List.of()));
    }

    /**
     * @param key a key's name
     * @return true if some task produces it
     */
    public boolean hasKey(String key) {
        return variablesByName.containsKey(key);
    }

    private TaskRuntime runtime(String task) {
        return runtimes.stream().filter(r -> r.name().equals(task)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no task '" + task + "'; tasks: "
                        + runtimes.stream().map(TaskRuntime::name).collect(Collectors.joining(", "))));
    }

    /**
     * Adds a listener after building, e.g. one that needs {@link #tasks()} to size itself.
     *
     * @param listener receives every event from the start on
     * @throws IllegalStateException if the monitor has already started
     */
    public void addListener(MonitorListener listener) {
        Objects.requireNonNull(listener, "listener");
        synchronized (lifecycle) {
            if (phase != Phase.READY) {
                throw new IllegalStateException("listeners must be added before the monitor starts");
            }
            listeners.add(listener);
        }
    }

    /**
     * Registers a handler that receives the report once, after every task has stopped and
     * terminated. Handlers run on the thread that completes {@link #stop()}.
     *
     * @param handler the handler
     */
    public void onTermination(Consumer<Report> handler) {
        terminationHandlers.add(Objects.requireNonNull(handler, "handler"));
    }

    /**
     * Starts every task on its own platform thread, named {@code rtaware-<task>}, with
     * rate-monotonic Java priorities and the builder's {@link ThreadSetup}. Periodic tasks
     * are released on an absolute grid from now.
     *
     * @throws IllegalStateException if already started
     */
    public void start() {
        ClockWaiter waiter = clock instanceof ManualClock manual
                ? new ManualClockWaiter(manual, runtimes.size() + 1) : new ParkingClockWaiter(clock);
        begin(new ThreadedExecutor(clock, waiter, runtimes, this::requestStopFromTask, threadSetup, faults));
    }

    /** @return the executor once started, else null (tests on a manual clock step through it) */
    Executor executor() {
        synchronized (lifecycle) {
            return executor;
        }
    }

    /** @return framework faults so far (see {@link FrameworkErrorHandler}) */
    public long frameworkErrors() {
        return faults.count();
    }

    /**
     * Starts the tasks on a step executor driven by the caller; the clock must be a
     * {@link ManualClock}.
     *
     * @return the executor to step
     * @throws IllegalStateException if already started or the clock is not manual
     */
    public StepExecutor startStepped() {
        if (!(clock instanceof ManualClock manual)) {
            throw new IllegalStateException("the step executor needs a ManualClock, not " + clock);
        }
        StepExecutor step = new StepExecutor(manual, runtimes, this::stop, faults);
        begin(step);
        return step;
    }

    private void begin(Executor newExecutor) {
        synchronized (lifecycle) {
            if (phase != Phase.READY) {
                throw new IllegalStateException("monitor already started");
            }
            phase = Phase.RUNNING;
            executor = newExecutor;
            events.listeners(listeners.toArray(new MonitorListener[0]));
        }
        long started = executor.start();
        synchronized (lifecycle) {
            startNs = started;
        }
    }

    /**
     * Installs a JVM shutdown hook (Ctrl-C, SIGTERM) that stops the monitor, so the tasks are
     * terminated and the report is written on every way out.
     *
     * @return the hook thread (remove it with {@code Runtime.removeShutdownHook} if needed)
     */
    public Thread installShutdownHook() {
        Thread hook = new Thread(this::stop, "rtaware-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        return hook;
    }

    /**
     * Termination: stops releasing tasks, waits for their threads, calls {@code terminate()} on
     * each in registration order, builds the report and calls the termination handlers. Returns
     * after all of that; later calls wait for the first to finish.
     *
     * @return the report
     */
    public Report stop() {
        boolean first;
        synchronized (lifecycle) {
            first = phase == Phase.RUNNING;
            if (phase == Phase.READY) {
                phase = Phase.TERMINATED;
                startNs = clock.nanos();
                first = true;
            } else if (first) {
                phase = Phase.TERMINATED;
            }
        }
        if (!first) {
            awaitUninterruptibly();
            return report;
        }
        try {
            if (executor != null) {
                executor.stopAndJoin();
            }
            tasksStopped = true;
            stopNs = clock.nanos();
            for (TaskRuntime runtime : runtimes) {
                try {
                    runtime.spec().task().terminate();
                } catch (Exception e) {
                    System.err.println("rtaware: task '" + runtime.name() + "' failed to terminate: " + e);
                }
                runtime.setState(TaskState.TERMINATED, stopNs);
            }
            report = buildReport();
            for (Consumer<Report> handler : terminationHandlers) {
                try {
                    handler.accept(report);
                } catch (Throwable t) {
                    faults.report("termination handler", t);
                }
            }
        } finally {
            terminated.countDown();
        }
        return report;
    }

    /** Called from a task thread under STOP_ALL: stop on another thread (a thread cannot join itself). */
    private void requestStopFromTask() {
        Thread stopper = new Thread(this::stop, "rtaware-stop");
        stopper.setDaemon(false);
        stopper.start();
    }

    /**
     * Waits until the monitor has terminated (after {@link #stop()} or a STOP_ALL error).
     *
     * @param timeout how long to wait
     * @return true if terminated
     * @throws InterruptedException if interrupted while waiting
     */
    public boolean awaitTermination(Duration timeout) throws InterruptedException {
        return terminated.await(timeout.toNanos(), TimeUnit.NANOSECONDS);
    }

    /**
     * @return true once termination has begun (by {@link #stop()}, a shutdown hook or a STOP_ALL
     *     error): observers should stop drawing conclusions from data that is about to stop
     */
    public boolean isStopping() {
        synchronized (lifecycle) {
            return phase == Phase.TERMINATED;
        }
    }

    /** @return true once the termination handlers have run */
    public boolean isTerminated() {
        return terminated.getCount() == 0;
    }

    private void awaitUninterruptibly() {
        boolean interrupted = false;
        while (true) {
            try {
                terminated.await();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * The period changes of adaptive tasks, in the order each task made them.
     *
     * @return every task's changes, tasks in registration order; empty without adaptive periods
     * @throws IllegalStateException before the task threads have stopped (the history is theirs);
     *     termination handlers may call it
     */
    public List<PeriodChange> periodHistory() {
        if (!tasksStopped) {
            throw new IllegalStateException("the period history is complete only after the monitor has stopped");
        }
        List<PeriodChange> all = new ArrayList<>();
        runtimes.forEach(r -> all.addAll(r.periodHistory()));
        return all;
    }

    /** @return the final report, or null before termination */
    public Report report() {
        return report;
    }

    private Report buildReport() {
        List<TaskReport> tasks = runtimes.stream().map(TaskRuntime::report).toList();
        long releases = tasks.stream().mapToLong(TaskReport::releases).sum();
        long misses = tasks.stream().mapToLong(TaskReport::misses).sum();
        List<DataReport> data = new ArrayList<>();
        for (StateVariable<?> variable : variables) {
            String name = variable.key().name();
            FeedStats feed = variable.feedStats();
            data.add(new DataReport(name, producers.get(name), consumers.getOrDefault(name, List.of()),
                    feed.commits(), TaskRuntime.round2(feed.rateHz()),
                    new DataReport.Interval(ms(feed.minIntervalNs()), ms(feed.meanIntervalNs()),
                            ms(feed.maxIntervalNs()))));
        }
        data.sort((a, b) -> a.name().compareTo(b.name()));
        return new Report(Report.SCHEMA, clock.timeScale(), Math.round((stopNs - startNs) / 1e6) / 1e3,
                releases == 0 ? 0.0 : TaskRuntime.round2(100.0 * misses / releases), tasks, data, faults.count());
    }

    private static double ms(double ns) {
        return Math.round(ns / 1e3) / 1e3;
    }

    /**
     * Collects tasks and listeners, then initializes and verifies them. Not thread-safe.
     */
    public static final class Builder {

        private final Clock clock;
        private final List<TaskSpec> specs = new ArrayList<>();
        private final List<MonitorListener> listeners = new ArrayList<>();
        private ErrorPolicy defaultPolicy = ErrorPolicy.CONTINUE;
        private AdaptivePolicy adaptivePolicy;
        private ThreadSetup threadSetup;
        private FrameworkErrorHandler errorHandler;

        private Builder(Clock clock) {
            this.clock = Objects.requireNonNull(clock, "clock");
        }

        /**
         * @param policy the error policy of tasks added later without one (default CONTINUE)
         * @return this builder
         */
        public Builder defaultErrorPolicy(ErrorPolicy policy) {
            this.defaultPolicy = Objects.requireNonNull(policy, "policy");
            return this;
        }

        /**
         * @param name the task's unique name
         * @param schedule when it runs
         * @param task the behavior
         * @return this builder
         */
        public Builder task(String name, Schedule schedule, Task task) {
            return task(new TaskSpec(name, schedule, defaultPolicy, task));
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
         * Enables adaptive periods: tasks whose periodic schedule declares a period range
         * ({@link Schedule#adaptive}) have their period moved inside it by {@code policy}. Off by
         * default, when such tasks run at their initial period.
         *
         * @param policy the rule, e.g. {@link AdaptivePolicy#defaults()}; null turns it off
         * @return this builder
         */
        public Builder adaptivePeriods(AdaptivePolicy policy) {
            this.adaptivePolicy = policy;
            return this;
        }

        /**
         * @param setup called on each task thread at its start (e.g. to set SCHED_FIFO); null for
         *     none. The step executor does not call it.
         * @return this builder
         */
        public Builder threadSetup(ThreadSetup setup) {
            this.threadSetup = setup;
            return this;
        }

        /**
         * @param handler receives every fault on the framework's side (listeners, termination
         *     handlers, thread setup, executors), each already contained and counted; default: a
         *     {@link RateLimitedErrorPrinter} on standard error
         * @return this builder
         */
        public Builder errorHandler(FrameworkErrorHandler handler) {
            this.errorHandler = Objects.requireNonNull(handler, "handler");
            return this;
        }

        /**
         * @param listener receives every event
         * @return this builder
         */
        public Builder listener(MonitorListener listener) {
            listeners.add(Objects.requireNonNull(listener, "listener"));
            return this;
        }

        /**
         * Initialization: calls {@code initialize} on every task, then verifies names, schedules
         * and the data graph.
         *
         * @return a monitor ready to start
         * @throws ConfigurationException listing every violation found
         */
        public Monitor build() {
            List<String> violations = new ArrayList<>();
            Map<String, Integer> seen = new LinkedHashMap<>();
            for (TaskSpec spec : specs) {
                if (seen.merge(spec.name(), 1, Integer::sum) == 2) {
                    violations.add("task name '" + spec.name() + "' is used by more than one task; names must be unique");
                }
                if (spec.name().isBlank()) {
                    violations.add("a task has an empty name");
                }
                checkSchedule(spec, violations);
            }

            List<Setup> setups = new ArrayList<>();
            for (TaskSpec spec : specs) {
                Setup setup = new Setup(spec, clock);
                try {
                    spec.task().initialize(setup);
                } catch (Exception e) {
                    violations.add("task '" + spec.name() + "' failed to initialize: " + e.getClass().getSimpleName()
                            + (e.getMessage() == null ? "" : ": " + e.getMessage()));
                }
                setup.closed = true;
                setup.violations.forEach(violations::add);
                setups.add(setup);
            }

            // Declaration order: error messages list produced keys as the tasks declared them.
            Map<String, Setup> producerOf = new LinkedHashMap<>();
            Map<String, Key<?>> producedKey = new LinkedHashMap<>();
            for (Setup setup : setups) {
                for (OutputHandle<?> out : setup.outputs) {
                    String key = out.key().name();
                    Setup other = producerOf.get(key);
                    if (other == setup) {
                        continue; // declared twice by one task: already reported by its setup
                    }
                    if (other != null) {
                        violations.add("key '" + key + "' is produced by tasks '" + other.spec.name() + "' and '"
                                + setup.spec.name() + "'; a key has exactly one producer");
                    } else {
                        producerOf.put(key, setup);
                        producedKey.put(key, out.key());
                    }
                }
            }
            Map<String, List<String>> consumersOf = new TreeMap<>();
            for (Setup setup : setups) {
                for (InputHandle<?> in : setup.inputs) {
                    String key = in.key().name();
                    Key<?> produced = producedKey.get(key);
                    if (produced == null) {
                        violations.add("task '" + setup.spec.name() + "' consumes '" + key
                                + "' but no task produces it; produced keys: "
                                + (producedKey.isEmpty() ? "(none)" : String.join(", ", producedKey.keySet())));
                    } else if (!produced.type().equals(in.key().type())) {
                        violations.add("task '" + setup.spec.name() + "' consumes '" + key + "' as "
                                + in.key().type().getSimpleName() + " but task '" + producerOf.get(key).spec.name()
                                + "' produces it as " + produced.type().getSimpleName());
                    }
                    consumersOf.computeIfAbsent(key, k -> new ArrayList<>()).add(setup.spec.name());
                }
            }
            if (!violations.isEmpty()) {
                throw new ConfigurationException(violations);
            }

            List<StateVariable<?>> variables = new ArrayList<>();
            Map<String, StateVariable<?>> byName = new LinkedHashMap<>();
            Map<String, String> producers = new LinkedHashMap<>();
            for (Map.Entry<String, Key<?>> entry : producedKey.entrySet()) {
                StateVariable<?> variable = newVariable(entry.getValue());
                variables.add(variable);
                byName.put(entry.getKey(), variable);
                producers.put(entry.getKey(), producerOf.get(entry.getKey()).spec.name());
            }
            FrameworkFaults faults = new FrameworkFaults(
                    errorHandler != null ? errorHandler : new RateLimitedErrorPrinter());
            ListenerFanOut events = new ListenerFanOut(faults);
            List<TaskRuntime> runtimes = new ArrayList<>();
            for (Setup setup : setups) {
                for (OutputHandle<?> out : setup.outputs) {
                    String key = out.key().name();
                    out.bind(byName.get(key), variables.indexOf(byName.get(key)));
                }
                for (InputHandle<?> in : setup.inputs) {
                    in.bind(byName.get(in.key().name()));
                }
                TaskRuntime runtime = new TaskRuntime(setup.spec, runtimes.size(), clock, events,
                        setup.inputs.toArray(new InputHandle<?>[0]), setup.outputs.toArray(new OutputHandle<?>[0]));
                if (adaptivePolicy != null) {
                    runtime.adaptive(adaptivePolicy);
                }
                runtimes.add(runtime);
            }
            return new Monitor(clock, List.copyOf(runtimes), List.copyOf(variables), producers, consumersOf, listeners,
                    threadSetup, events, faults);
        }

        private static <T extends StateValue<T>> StateVariable<T> newVariable(Key<T> key) {
            return new StateVariable<>(key);
        }

        private static void checkSchedule(TaskSpec spec, List<String> violations) {
            String task = "task '" + spec.name() + "'";
            if (spec.schedule() instanceof Schedule.Periodic p) {
                if (p.periodNs() <= 0) {
                    violations.add(task + " has period " + Durations.format(p.periodNs()) + "; a period must be positive");
                } else if (p.deadlineNs() <= 0 || p.deadlineNs() > p.periodNs()) {
                    violations.add(task + " has deadline " + Durations.format(p.deadlineNs())
                            + "; it must be positive and at most the period " + Durations.format(p.periodNs()));
                }
                if (p.isAdaptive() && p.periodNs() > 0
                        && (p.minPeriodNs() <= 0 || p.minPeriodNs() > p.periodNs() || p.periodNs() > p.maxPeriodNs())) {
                    violations.add(task + " has period range " + Durations.format(p.minPeriodNs()) + ".."
                            + Durations.format(p.maxPeriodNs()) + " and period " + Durations.format(p.periodNs())
                            + "; it needs 0 < min <= period <= max");
                }
                if (p.offsetNs() < 0) {
                    violations.add(task + " has offset " + Durations.format(p.offsetNs()) + "; an offset cannot be negative");
                }
            } else if (spec.schedule() instanceof Schedule.Once o && o.offsetNs() < 0) {
                violations.add(task + " has offset " + Durations.format(o.offsetNs()) + "; an offset cannot be negative");
            }
        }
    }

    /** The declarations of one task during initialization. */
    private static final class Setup implements TaskSetup {
        final TaskSpec spec;
        final Clock clock;
        final List<InputHandle<?>> inputs = new ArrayList<>();
        final List<OutputHandle<?>> outputs = new ArrayList<>();
        final List<String> violations = new ArrayList<>();
        boolean closed;

        Setup(TaskSpec spec, Clock clock) {
            this.spec = spec;
            this.clock = clock;
        }

        @Override
        public String taskName() {
            return spec.name();
        }

        @Override
        public Schedule schedule() {
            return spec.schedule();
        }

        @Override
        public Clock clock() {
            return clock;
        }

        @Override
        public <T extends StateValue<T>> Input<T> consume(Key<T> key) {
            return addInput(key, Long.MAX_VALUE);
        }

        @Override
        public <T extends StateValue<T>> Input<T> consume(Key<T> key, Duration maxAge) {
            long maxAgeNs = maxAge.toNanos();
            if (maxAgeNs <= 0) {
                violations.add("task '" + spec.name() + "' declares max age " + maxAge + " for '" + key.name()
                        + "'; it must be positive");
            }
            return addInput(key, maxAgeNs);
        }

        private <T extends StateValue<T>> Input<T> addInput(Key<T> key, long maxAgeNs) {
            checkOpen();
            if (inputs.stream().anyMatch(i -> i.key().name().equals(key.name()))
                    || outputs.stream().anyMatch(o -> o.key().name().equals(key.name()))) {
                violations.add("task '" + spec.name() + "' declares '" + key.name() + "' more than once");
            }
            InputHandle<T> handle = new InputHandle<>(key, maxAgeNs);
            inputs.add(handle);
            return handle;
        }

        @Override
        public <T extends StateValue<T>> Output<T> produce(Key<T> key) {
            checkOpen();
            if (inputs.stream().anyMatch(i -> i.key().name().equals(key.name()))
                    || outputs.stream().anyMatch(o -> o.key().name().equals(key.name()))) {
                violations.add("task '" + spec.name() + "' declares '" + key.name() + "' more than once");
            }
            OutputHandle<T> handle = new OutputHandle<>(key);
            outputs.add(handle);
            return handle;
        }

        private void checkOpen() {
            if (closed) {
                throw new IllegalStateException("task '" + spec.name() + "' declared data after initialization");
            }
        }
    }
}
