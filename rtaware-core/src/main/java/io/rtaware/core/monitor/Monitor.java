package io.rtaware.core.monitor;

import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.conditions.ThreadTimerSlack;
import io.rtaware.core.data.FeedStats;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.SummaryTable;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.ReactionConstraint;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import io.rtaware.core.time.ManualClock;
import io.rtaware.core.time.MonotonicSleeper;
import java.io.PrintStream;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
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
 * {@link #stop()} is the Termination state: tasks stop, {@code terminate()} is called on each
 * (first on the tasks that {@link Task#stopsFirst() stop first}: those that command the robot),
 * and the {@link Report} is built and handed to the termination handlers.
 * {@link #runUntilStopped()} is all of it for a program's {@code main}: start, stop on Ctrl-C,
 * wait for the end, print the summary.
 *
 * <p>Thread-safe: {@code stop()} may be called from any thread, any number of times, from a
 * task's cycle and from a termination handler too.
 */
public final class Monitor {

    private enum Phase { READY, RUNNING, TERMINATED }

    private final Clock clock;
    private final List<TaskRuntime> runtimes;
    private final DataGraph graph;
    private final List<Consumer<Report>> terminationHandlers = new CopyOnWriteArrayList<>();
    private final List<Runnable> tasksStoppedHandlers = new CopyOnWriteArrayList<>();
    private final List<MonitorListener> listeners;
    private final ThreadSetup threadSetup;
    private final ThreadTimerSlack timerSlack = ThreadTimerSlack.ofThisMachine();
    /** How task threads of the threaded executor sleep on a real clock; null: they park. */
    private final MonotonicSleeper sleeper;
    private final ExecutorKind executorKind;
    private final ListenerFanOut events;
    private final FrameworkFaults faults;
    /** Reaction constraints declared by tasks at initialization, by task name. */
    private final Map<String, ReactionConstraint> reactions;
    /** The tasks that {@link Task#stopsFirst() stop first}, then the others; each in registration order. */
    private final List<TaskRuntime> stopFirst;
    private final List<TaskRuntime> stopAfter;
    private final CountDownLatch terminated = new CountDownLatch(1);
    private final Object lifecycle = new Object();
    private Phase phase = Phase.READY;
    /** The thread that runs the termination, once it has begun. */
    private volatile Thread stopping;
    private Executor executor;
    private long startNs;
    private long stopNs;
    private volatile Report report;
    /** Set once every task thread has returned: their own state may then be read. */
    private volatile boolean tasksStopped;

    private Monitor(Clock clock, List<TaskRuntime> runtimes, DataGraph graph, List<MonitorListener> listeners,
                    ThreadSetup threadSetup, MonotonicSleeper sleeper, ListenerFanOut events, FrameworkFaults faults,
                    ExecutorKind executorKind, Map<String, ReactionConstraint> reactions) {
        this.clock = clock;
        this.executorKind = executorKind;
        this.runtimes = runtimes;
        this.graph = graph;
        this.listeners = new ArrayList<>(listeners);
        this.threadSetup = threadSetup;
        this.sleeper = sleeper;
        this.events = events;
        this.faults = faults;
        this.reactions = Map.copyOf(reactions);
        this.stopFirst = runtimes.stream().filter(r -> r.spec().task().stopsFirst()).toList();
        this.stopAfter = runtimes.stream().filter(r -> !r.spec().task().stopsFirst()).toList();
    }

    /**
     * What the monitor itself keeps per task on the heap (histograms of execution time and
     * lateness, the latest execution times for the live p99, counters), so that a command can
     * refuse a task set that cannot fit before it allocates anything: about 32 KB, from
     * HdrHistogram's footprint estimate of the histograms plus the rest as measured, under either
     * executor.
     *
     * @return bytes per task, not counting the task's own data
     */
    public static long estimatedHeapBytesPerTask() {
        return TaskRuntime.estimatedHeapBytes();
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
        return graph.keyNames();
    }

    /**
     * @return the keys by key index (see {@link MonitorListener#onCommitValue}), in the order
     *     of {@link #keyNames()}
     */
    public List<Key<?>> keys() {
        return graph.variables().stream().<Key<?>>map(v -> v.key()).toList();
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
     * The releases of every task so far, without building each task's {@link TaskCounters} (whose
     * live execution-time p99 sorts the task's latest cycles): cheap enough to read while
     * thousands of tasks run, and allocation-free. Safe at any time from any thread.
     *
     * @return the sum over the tasks of {@link TaskCounters#releases()}
     */
    public long totalReleases() {
        long sum = 0;
        for (TaskRuntime runtime : runtimes) {
            sum += runtime.statistics().releases();
        }
        return sum;
    }

    /**
     * @param key a key's name
     * @return its live feed statistics
     */
    public FeedStats feed(String key) {
        return graph.variable(key).feedStats();
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
        return graph.read(key, target);
    }

    /**
     * @param key a key's name
     * @return the name of the task that produces it
     * @throws IllegalArgumentException if no task produces it
     */
    public String producer(String key) {
        return graph.producer(key);
    }

    /**
     * @param key a key's name
     * @return the names of the tasks that consume it, empty if none
     * @throws IllegalArgumentException if no task produces it
     */
    public List<String> consumers(String key) {
        return graph.consumers(key);
    }

    /**
     * @param key a key's name
     * @return true if some task produces it
     */
    public boolean hasKey(String key) {
        return graph.hasKey(key);
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
     * Registers a handler that runs once, as soon as every task has stopped and terminated and
     * before the report is built: the end of what the tasks did, for whatever measures the run
     * beside the monitor (the machine's conditions, see
     * {@link io.rtaware.core.conditions.ConditionsMeter.Span#end()}), so that building the report
     * of thousands of tasks, and the collector's work after it, is not counted as the run's. Runs
     * on the thread that completes {@link #stop()}; a fault is reported and the stop goes on.
     *
     * @param handler the handler
     */
    public void onTasksStopped(Runnable handler) {
        tasksStoppedHandlers.add(Objects.requireNonNull(handler, "handler"));
    }

    /**
     * Starts the tasks on the builder's executor: by default every task on its own platform
     * thread, named {@code rtaware-<task>}, with rate-monotonic Java priorities and the builder's
     * {@link ThreadSetup}; with {@link ExecutorKind#pooled()} the periodic tasks that do not block
     * on a few workers ({@link PooledExecutor}). Periodic tasks are released on an absolute grid
     * from now.
     *
     * @throws IllegalStateException if already started
     */
    public void start() {
        ThreadSetup setup = new ObservedSetup(threadSetup, timerSlack);
        if (executorKind instanceof ExecutorKind.Pooled pool) {
            begin(new PooledExecutor(clock, newWaiter(), runtimes, pool.workers(), pool.order(), this::requestStopFromTask,
                    setup, faults));
        } else {
            begin(new ThreadedExecutor(clock, newWaiter(), runtimes, this::requestStopFromTask, setup, faults));
        }
    }

    /**
     * The timer slack of the threads that run this monitor's cycles (task threads and pool
     * workers), as each read it once its {@link ThreadSetup} had run: 50 000 ns is Linux's
     * default, 1 ns what {@code io.rtaware.rt.MinimalTimerSlack} asks for. Empty before
     * {@link #start()}, under the step executor, and where {@code /proc} does not tell.
     *
     * @return the observation (thread-safe)
     */
    public ThreadTimerSlack timerSlack() {
        return timerSlack;
    }

    /** The builder's setup, then a look at what the thread's timer slack became. */
    private record ObservedSetup(ThreadSetup setup, ThreadTimerSlack slack) implements ThreadSetup {
        @Override
        public void onTaskThreadStart(TaskInfo task, int rmRank, int taskCount) {
            observeAfter(setup == null ? null : () -> setup.onTaskThreadStart(task, rmRank, taskCount));
        }

        @Override
        public void onPoolWorkerStart(int worker, int rmRank, int taskCount) {
            observeAfter(setup == null ? null : () -> setup.onPoolWorkerStart(worker, rmRank, taskCount));
        }

        /** Forwarded only: the timer slack observed is that of the threads that run cycles. */
        @Override
        public void onWatchdogStart(int taskCount) {
            if (setup != null) {
                setup.onWatchdogStart(taskCount);
            }
        }

        private void observeAfter(Runnable setupOfThisThread) {
            try {
                if (setupOfThisThread != null) {
                    setupOfThisThread.run();
                }
            } finally {
                slack.observeCurrentThread();
            }
        }
    }

    private ClockWaiter newWaiter() {
        return ClockWaiter.forClock(clock, sleeper);
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
            for (MonitorListener listener : listeners) {
                if (listener instanceof ConsoleReporter console) {
                    console.reportFaultsTo(faults); // its printer's faults, as the listeners' own
                }
            }
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
        Thread hook = new Thread(this::stop, ThreadNames.SHUTDOWN);
        Runtime.getRuntime().addShutdownHook(hook);
        return hook;
    }

    /**
     * Termination: stops releasing tasks; waits for the threads of the tasks that
     * {@link Task#stopsFirst() stop first} and calls {@code terminate()} on them; waits for every
     * other task thread and calls {@code terminate()} on the rest (each group in registration
     * order); builds the report and calls the termination handlers. Returns after all of that;
     * later calls wait for the first to finish, except two that return at once, with the report
     * once it is built and null before: a call from the thread that is terminating (a task's
     * {@code terminate()}, a termination handler), and one from a task's cycle while another
     * thread terminates (the termination waits for that cycle to return).
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
            if (first) {
                stopping = Thread.currentThread();
            }
        }
        if (!first) {
            Thread caller = Thread.currentThread();
            if (stopping != caller && (executor == null || !executor.runsCyclesOn(caller))) {
                awaitUninterruptibly();
            }
            return report;
        }
        try {
            if (executor != null) {
                executor.stopReleasing();
                executor.joinThreadsOf(stopFirst);
            }
            terminate(stopFirst, clock.nanos(), faults);
            if (executor != null) {
                executor.stopAndJoin();
            }
            tasksStopped = true;
            stopNs = clock.nanos();
            terminate(stopAfter, stopNs, faults);
            for (Runnable handler : tasksStoppedHandlers) {
                try {
                    handler.run();
                } catch (Throwable t) {
                    faults.report("tasks-stopped handler", t);
                }
            }
            report = ReportBuilder.build(clock.timeScale(), stopNs - startNs, runtimes, graph, faults.count(),
                    reactions);
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

    private static void terminate(List<TaskRuntime> tasks, long nowNs, FrameworkFaults faults) {
        for (TaskRuntime runtime : tasks) {
            try {
                runtime.spec().task().terminate();
            } catch (Exception e) {
                faults.report("terminate() of task '" + runtime.name() + "'", e);
            }
            runtime.setState(TaskState.TERMINATED, nowNs);
        }
    }

    /**
     * Runs the tasks until the run is stopped, printing the summary to standard output: what a
     * program's {@code main} needs in one call. See {@link #runUntilStopped(PrintStream)}.
     *
     * @return the report
     * @throws IllegalStateException if the monitor has already started
     */
    public Report runUntilStopped() {
        return runUntilStopped(System.out);
    }

    /**
     * Runs the tasks until the run is stopped: the lifecycle of a program whose {@code main}
     * builds a monitor and hands over to it. It installs a JVM shutdown hook that stops the
     * monitor (Ctrl-C, SIGTERM, {@code System.exit}), starts the tasks, prints one line saying they
     * run, and waits until the run ends: by the hook, by {@link #stop()} on another thread or in a
     * task's cycle, by a task's {@link io.rtaware.core.task.ErrorPolicy#STOP_ALL}, or by an
     * interrupt of the calling thread (which stops the run and stays set). The end is
     * {@link #stop()}: the tasks that {@link Task#stopsFirst() stop first} are terminated first,
     * then the others, then the termination handlers registered before this call run, then the
     * {@link SummaryTable} is printed; the shutdown hook returns only after that, so the JVM exits
     * after the summary. A run that ended otherwise removes its hook. Call it from the
     * program's main thread; after Ctrl-C the JVM exits once the summary is printed, so work that
     * must happen at the end belongs in a termination handler ({@link #onTermination}), not after
     * this call.
     *
     * @param out where the line at the start and the summary go
     * @return the report
     * @throws IllegalStateException if the monitor has already started
     */
    public Report runUntilStopped(PrintStream out) {
        return runUntilStopped(out, ShutdownHooks.JVM);
    }

    /** {@link #runUntilStopped(PrintStream)} with the hook installed in {@code hooks} (a test's). */
    Report runUntilStopped(PrintStream out, ShutdownHooks hooks) {
        Objects.requireNonNull(out, "out");
        synchronized (lifecycle) {
            if (phase != Phase.READY) {
                throw new IllegalStateException("runUntilStopped needs a monitor that has not started");
            }
        }
        Consumer<Report> summary = finished -> {
            out.print(SummaryTable.format(finished));
            out.flush();
        };
        terminationHandlers.add(summary);
        Thread hook = new Thread(this::stop, ThreadNames.SHUTDOWN);
        hooks.add(hook);
        try {
            start();
        } catch (RuntimeException | Error e) {
            if (e instanceof IllegalStateException && isStopping()) {
                // Ctrl-C came before the start: the hook has stopped the monitor and printed the summary.
                return awaitEnd(hooks, hook);
            }
            terminationHandlers.remove(summary);
            hooks.remove(hook);
            throw e;
        }
        out.println("rtaware: running " + runtimes.size() + (runtimes.size() == 1 ? " task" : " tasks")
                + "; Ctrl-C stops them and prints the summary");
        out.flush();
        return awaitEnd(hooks, hook);
    }

    /**
     * Waits for the termination (an interrupt stops the monitor, and stays set), then removes the
     * hook unless the JVM is exiting.
     */
    private Report awaitEnd(ShutdownHooks hooks, Thread hook) {
        boolean interrupted = false;
        while (!isTerminated()) {
            try {
                terminated.await();
            } catch (InterruptedException e) {
                interrupted = true;
                stop();
            }
        }
        try {
            hooks.remove(hook);
        } catch (IllegalStateException shuttingDown) {
            // The JVM is exiting: the hook has stopped the monitor (or waits until it has).
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        return report;
    }

    /** Called from a task thread under STOP_ALL: stop on another thread (a thread cannot join itself). */
    private void requestStopFromTask() {
        Thread stopper = new Thread(this::stop, ThreadNames.STOP);
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
        private MonotonicSleeper sleeper;
        private FrameworkErrorHandler errorHandler;
        private ExecutorKind executorKind = ExecutorKind.threaded();

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
         * How the threaded executor's task threads sleep until their next release on a real or
         * scaled clock: with this sleeper (e.g. {@code clock_nanosleep}, one system call per
         * release) instead of {@code LockSupport.parkNanos}. A stop is then noticed within 100 ms
         * (a sleeping task thread cannot be unparked). The watchdog, pool workers and manual
         * clocks are unaffected.
         *
         * @param sleeper the sleeper; null (the default) to park
         * @return this builder
         */
        public Builder sleeper(MonotonicSleeper sleeper) {
            this.sleeper = sleeper;
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
         * @param kind the executor {@link Monitor#start()} uses: {@link ExecutorKind#threaded()}
         *     (default, one thread per task) or {@link ExecutorKind#pooled()} (a few workers for
         *     the periodic tasks that do not block)
         * @return this builder
         */
        public Builder executor(ExecutorKind kind) {
            this.executorKind = Objects.requireNonNull(kind, "kind");
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

        /** Shared by the tasks without inputs or outputs: fewer objects for a cycle to touch. */
        private static final InputHandle<?>[] NO_INPUTS = new InputHandle<?>[0];
        private static final OutputHandle<?>[] NO_OUTPUTS = new OutputHandle<?>[0];

        /**
         * Initialization: calls {@code initialize} on every task, then verifies names, schedules
         * and the data graph.
         *
         * @return a monitor ready to start
         * @throws ConfigurationException listing every violation found
         */
        public Monitor build() {
            List<DeclaringSetup> declared = new ArrayList<>();
            for (TaskSpec spec : specs) {
                declared.add(DeclaringSetup.initialize(spec, clock));
            }
            DataGraph graph = GraphValidator.validateAndBind(declared);

            FrameworkFaults faults = new FrameworkFaults(
                    errorHandler != null ? errorHandler : new RateLimitedErrorPrinter());
            ListenerFanOut events = new ListenerFanOut(faults);
            List<TaskRuntime> runtimes = new ArrayList<>();
            StatisticsTable statistics = new StatisticsTable(declared.size());
            ReleaseTable releases = new ReleaseTable(declared.size());
            for (DeclaringSetup declarations : declared) {
                TaskRuntime runtime = new TaskRuntime(declarations.spec, runtimes.size(), statistics, releases, clock,
                        events,
                        declarations.inputs.toArray(NO_INPUTS), declarations.outputs.toArray(NO_OUTPUTS));
                if (adaptivePolicy != null) {
                    runtime.adaptive(adaptivePolicy);
                }
                runtimes.add(runtime);
            }
            Map<String, ReactionConstraint> reactions = new LinkedHashMap<>();
            for (DeclaringSetup declarations : declared) {
                if (declarations.reaction() != null) {
                    reactions.put(declarations.spec.name(), declarations.reaction());
                }
            }
            return new Monitor(clock, List.copyOf(runtimes), graph, listeners, threadSetup, sleeper, events, faults,
                    executorKind, reactions);
        }
    }
}
