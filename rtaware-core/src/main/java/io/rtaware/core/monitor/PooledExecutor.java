package io.rtaware.core.monitor;

import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.time.Clock;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.AtomicReferenceArray;
import java.util.concurrent.locks.LockSupport;

/**
 * A few worker threads release the periodic tasks that do not block, in deadline order: for
 * thousands of tasks, where a thread per task costs more than the work. Continuous tasks, once
 * tasks and tasks that {@link io.rtaware.core.task.Task#blocks() block} keep a thread of their
 * own, on an inner {@link ThreadedExecutor}.
 *
 * <p>Each worker has a {@link Shard}: the timer structure of a block of consecutive pool slots,
 * two {@link TaskHeap}s under the shard's own lock: <em>waiting</em>, ordered by next release,
 * and <em>ready</em>, the releases already due, ordered by absolute deadline (earliest deadline
 * first) or by period (rate-monotonic). A worker, holding its shard's lock, puts back the tasks
 * it has just run (keyed by the release each {@link TaskRuntime} decided), moves every due
 * release to ready, takes up to {@link #MAX_BATCH} of the first ready tasks and runs them outside
 * the lock. With nothing due in its own shard it takes due releases from another's (work
 * stealing: what that shard's worker, busy with its batch, would run next); with nothing due
 * anywhere it parks with its {@link ClockWaiter} until the earliest release of any shard. A
 * worker about to run a batch wakes a parked one that would sleep past the earliest due release.
 * Under earliest deadline first with one fixed relative deadline for every pooled task, release
 * order is deadline order and workers take due releases straight from the waiting heap (see
 * {@link #releaseOrderIsRunOrder}).
 *
 * <p>Why shards: with one structure for all workers (the design before), each lock hold moved the
 * heap's lines and the state of every task between the cores' caches, because consecutive cycles
 * of a task ran on whichever worker came first; with a shard each, a task's state stays in the
 * cache of the core that ran it last, and the locks are uncontended but for a steal. The order
 * is earliest deadline first within a shard and across shards up to a batch: a worker whose own
 * shard has a due release does not look at the others. The shard's lock is the happens-before
 * edge between the workers that run one task's consecutive cycles (a stolen task is put back
 * under it). Every rule of what a cycle means stays the runtime's: the same grid, misses, skips
 * and counts as on the threaded executor (a release that waited for a free worker is late, and
 * one still waiting past its next grid point is skipped by the same rule as after an overrun).
 *
 * <p>A watchdog thread reports misses at the deadline, as on the threaded executor, but it only
 * looks at the cycles the workers run now and the rest of their batches (one slot each per
 * worker), not at every task.
 *
 * <p>The pooled tasks' lateness and execution times are recorded into their histograms by a
 * {@link StatisticsRecorder} thread, which a worker wakes when it has run releases and finds
 * nothing more due: a drain only notes the values (the recording was the largest cost of a drain
 * of 10 000 in-phase releases that a release does not need; docs/performance.md).
 *
 * <p>Each worker, the pool's watchdog and the inner executor's threads register with the one
 * {@link ClockWaiter} and wait and are woken through the {@link ClockWaiter.Party} they get.
 * Workers are made by a
 * {@link ThreadFactory} that runs {@link ThreadSetup#onPoolWorkerStart} on each before its first
 * release (with the rank of the shortest-period pooled task), and the start instant is taken
 * once every worker has run it; the tasks with their own thread run
 * {@link ThreadSetup#onTaskThreadStart}.
 *
 * <p>Steady state allocates nothing: heaps and slots are arrays sized at construction, the locks
 * are object monitors. Thread-safe: started once, stopped once, by the monitor.
 */
final class PooledExecutor implements Executor {

    /**
     * Most due releases a worker takes at once (its share of the ready ones, in order): one lock
     * hold for up to this many cycles instead of one per cycle, which is what lets two workers
     * release 10 000 tasks at 100 Hz. A release claimed in a batch waits as it would in the
     * ready heap; a later release with an earlier deadline waits for at most this many cycles.
     */
    static final int MAX_BATCH = 32;

    /**
     * Preparing the pooled tasks for the start took longer than this: the start instant is put
     * ahead by twice that time, so that starting each of them is done before its first release
     * (the tasks with a thread of their own, when there are any, keep the instant their executor
     * takes; on a manual clock preparing takes no time).
     */
    static final long START_AHEAD_ABOVE_NS = 500_000;

    private final Clock clock;
    private final ClockWaiter waiter;
    private final List<TaskRuntime> runtimes;
    private final ExecutorKind.PoolOrder order;
    private final Runnable stopAllRequest;
    private final FrameworkFaults faults;
    private final ThreadSetup threadSetup;
    /** The periodic tasks that do not block, by pool slot. */
    private final TaskRuntime[] pooled;
    /**
     * The release bookkeeping of every task (null without pooled tasks): workers read a batch's
     * next releases and deadlines there, in its dense rows, without reaching the runtimes.
     */
    private final ReleaseTable releases;
    /** Per pool slot: the task's index, its row in {@link #releases}. */
    private final int[] taskOf;
    /** The tasks with a thread of their own; null if there are none. */
    private final ThreadedExecutor dedicated;
    private final Watchdog watchdog;
    /** Records the pooled tasks' values into their histograms after the drains; null without pooled tasks. */
    private final StatisticsRecorder recorder;
    private final Thread[] workers;
    /** Each worker's handle in the waiter; set before the workers start. */
    private final ClockWaiter.Party[] workerParties;
    /**
     * What each worker runs now (null: nothing), at {@link #refSlot}; the watchdog scans these.
     * Written twice a release by its worker, so each worker's entry has cache lines of its own.
     */
    private final AtomicReferenceArray<TaskRuntime> current;
    /**
     * Per worker: the earliest deadline among the cycles of its batch not yet ended (the running
     * one included), {@link Long#MAX_VALUE} between batches. The watchdog sleeps until the
     * earliest of these, so a worker starting the next cycle of its batch finds it already due
     * to wake in time and does not wake it again: one wake per batch deadline, not one per cycle.
     * At {@link #longSlot}: each worker's entry has cache lines of its own.
     */
    private final AtomicLongArray batchDeadlineNs;

    /**
     * Entries between two workers' in {@link #batchDeadlineNs} and {@link #current}, which the
     * workers write every release: 128 bytes (two cache lines, which the adjacent-line prefetcher
     * fetches together), so that no two workers write one line. Packed, both workers' entries
     * shared a line that moved between the cores at every release (false sharing).
     */
    private static final int LONG_STRIDE = 128 / Long.BYTES;
    /** As {@link #LONG_STRIDE}, for references (4 bytes when compressed). */
    private static final int REF_STRIDE = 128 / Integer.BYTES;

    /** Each worker's share of the pooled tasks, by worker; a task's home is {@link #homeOf}. */
    private final Shard[] shards;
    /** Per pool slot: the shard its releases wait in. */
    private final int[] homeOf;
    /** Per worker: the world time it parks until, or {@link #NOT_PARKED}; set by itself, cleared by a waker. */
    private final AtomicLongArray parkedUntil;
    private static final long NOT_PARKED = Long.MIN_VALUE;

    /**
     * True when the waiting heap's order is already the order to run due releases in: earliest
     * deadline first, and every pooled task has the same fixed relative deadline, so release
     * order is deadline order (ties by slot in both). Workers then take due releases straight
     * from the waiting heap: no move to the ready heap, half the heap operations per release.
     * Set at start, before the workers go.
     */
    private boolean releaseOrderIsRunOrder;
    private volatile boolean running;

    /**
     * @param clock world time
     * @param waiter how every thread waits
     * @param runtimes every task of the monitor, by index
     * @param workerCount worker threads
     * @param order which due release runs first
     * @param stopAllRequest how a cycle stops the monitor (STOP_ALL)
     * @param threadSetup run on the dedicated task threads and on the workers; null for none
     * @param faults where framework faults go
     */
    PooledExecutor(Clock clock, ClockWaiter waiter, List<TaskRuntime> runtimes, int workerCount,
                   ExecutorKind.PoolOrder order, Runnable stopAllRequest, ThreadSetup threadSetup,
                   FrameworkFaults faults) {
        this.clock = clock;
        this.waiter = waiter;
        this.runtimes = runtimes;
        this.order = order;
        this.stopAllRequest = stopAllRequest;
        this.faults = faults;
        this.threadSetup = threadSetup;
        List<TaskRuntime> inPool = new ArrayList<>();
        List<TaskRuntime> own = new ArrayList<>();
        for (TaskRuntime runtime : runtimes) {
            (isPooled(runtime) ? inPool : own).add(runtime);
        }
        this.pooled = inPool.toArray(new TaskRuntime[0]);
        this.releases = pooled.length == 0 ? null : pooled[0].releaseTable();
        this.taskOf = new int[pooled.length];
        for (int slot = 0; slot < pooled.length; slot++) {
            taskOf[slot] = pooled[slot].index();
        }
        this.dedicated = own.isEmpty() ? null
                : new ThreadedExecutor(clock, waiter, own, stopAllRequest, threadSetup, faults);
        this.watchdog = new Watchdog(clock, waiter, faults, "pool watchdog", new WorkerSlots(), threadSetup,
                runtimes.size());
        this.recorder = pooled.length == 0 ? null : new StatisticsRecorder(pooled, faults);
        this.workers = new Thread[workerCount];
        this.workerParties = new ClockWaiter.Party[workerCount];
        // One stride of padding before the first worker's entry and after the last's: the
        // array's header and the objects beside it are not written by another core either.
        this.current = new AtomicReferenceArray<>(refSlot(workerCount) + REF_STRIDE);
        this.batchDeadlineNs = new AtomicLongArray(longSlot(workerCount) + LONG_STRIDE);
        for (int w = 0; w < workerCount; w++) {
            batchDeadlineNs.set(longSlot(w), Long.MAX_VALUE);
        }
        this.homeOf = new int[pooled.length];
        int[] sizes = new int[workerCount];
        for (int slot = 0; slot < pooled.length; slot++) {
            homeOf[slot] = (int) ((long) slot * workerCount / pooled.length);
            sizes[homeOf[slot]]++;
        }
        this.shards = new Shard[workerCount];
        for (int w = 0; w < workerCount; w++) {
            shards[w] = new Shard(sizes[w]);
        }
        this.parkedUntil = new AtomicLongArray(workerCount);
        // A compare-and-set that changes nothing, now: the JVM's first compare-and-set on any
        // AtomicLongArray links the VarHandle call inside it (2256 bytes of MethodType and its
        // kin), and the pool's first is a worker waking another (wakeParkedWorker), which with
        // a few tasks may not happen before steady state. It did, on a worker, in about one
        // run of the Epsilon guard in eight (found with a JVMTI allocation probe printing the
        // stack of every allocation on the pool's threads; docs/performance.md).
        parkedUntil.compareAndSet(0, NOT_PARKED, NOT_PARKED);
    }

    /** @return the index of a worker's entry in {@link #batchDeadlineNs} */
    private static int longSlot(int worker) {
        return (worker + 1) * LONG_STRIDE;
    }

    /** @return the index of a worker's entry in {@link #current} */
    private static int refSlot(int worker) {
        return (worker + 1) * REF_STRIDE;
    }

    /**
     * One worker's share of the pooled tasks (a block of consecutive slots): its timer structure,
     * two {@link TaskHeap}s guarded by the shard itself as lock. Its worker takes due releases
     * from it without meeting the other workers; a worker with nothing due takes (steals) due
     * releases from another's shard. The earliest release is published for workers deciding how
     * long to park and whether to steal.
     */
    private static final class Shard {
        /** The releases not yet due, by release time. */
        final TaskHeap waiting;
        /** The due releases, in the order they run (only when release order is not run order). */
        final TaskHeap ready;
        /**
         * The earliest world time this shard has a release due: {@link Long#MIN_VALUE} if one is
         * ready now, {@link Long#MAX_VALUE} if it has none. Written under the shard's lock.
         */
        volatile long earliestNs = Long.MAX_VALUE;

        Shard(int capacity) {
            waiting = new TaskHeap(capacity);
            ready = new TaskHeap(capacity);
        }

        /** Publishes the earliest release; holding the shard's lock. */
        void publishEarliest() {
            earliestNs = ready.size() > 0 ? Long.MIN_VALUE : waiting.peekKey();
        }
    }

    /** @return whether the pool runs this task (periodic and not blocking), else it gets a thread */
    static boolean isPooled(TaskRuntime runtime) {
        return runtime.isPeriodic() && !runtime.spec().task().blocks();
    }

    /** @return the waiter its threads wait with (tests on a manual clock step through it) */
    ClockWaiter waiter() {
        return waiter;
    }

    @Override
    public long start() {
        running = true;
        watchdog.prepare();
        CountDownLatch go = new CountDownLatch(1);
        CountDownLatch ready = new CountDownLatch(workers.length);
        ThreadFactory factory = new WorkerThreadFactory(fastestPooledRank(), ready);
        for (int w = 0; w < workers.length; w++) {
            int worker = w;
            workers[w] = factory.newThread(() -> work(worker, go));
            workerParties[w] = waiter.register(workers[w]);
            parkedUntil.set(w, NOT_PARKED);
        }
        for (Thread worker : workers) {
            worker.start();
        }
        // As on the threaded executor: the start instant is taken once every worker has run its
        // thread setup, so the setup never makes release 0 late.
        ThreadedExecutor.awaitUninterruptibly(ready);
        // The workers wait on the latch 'go': what is written here happens before their first step.
        releaseOrderIsRunOrder = order == ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST && oneFixedDeadline();
        long preparingNs = clock.nanos();
        for (TaskRuntime runtime : pooled) {
            runtime.watchedBy(watchdog);
            runtime.prepareStart(stopAllRequest, waiter.zeroCycleSpacingNs());
        }
        preparingNs = clock.nanos() - preparingNs;
        long startNs = dedicated != null ? dedicated.start() : startInstantNs(clock.nanos(), preparingNs);
        for (int slot = 0; slot < pooled.length; slot++) {
            TaskRuntime runtime = pooled[slot];
            runtime.begin(startNs);
            shards[homeOf[slot]].waiting.push(slot, runtime.nextReleaseNs());
        }
        for (Shard shard : shards) {
            shard.publishEarliest();
        }
        watchdog.start();
        if (recorder != null) {
            recorder.start();
        }
        go.countDown();
        return startNs;
    }

    /**
     * The start instant of a pool without tasks of their own thread: starting every task after
     * the instant takes about as long as preparing them did, with thousands of tasks milliseconds
     * by which every first release would be late (10 000 tasks: 7-14 ms on the development VM,
     * just after they were built, so each missed its first deadline). Past
     * {@link #START_AHEAD_ABOVE_NS}, the instant is put twice that far ahead.
     *
     * @param nowNs the clock when the tasks have been prepared
     * @param preparingNs how long preparing them took
     * @return the start instant
     */
    static long startInstantNs(long nowNs, long preparingNs) {
        return preparingNs > START_AHEAD_ABOVE_NS ? nowNs + 2 * preparingNs : nowNs;
    }

    private void work(int worker, CountDownLatch go) {
        ClockWaiter.Party party = workerParties[worker];
        try {
            go.await();
        } catch (InterruptedException e) {
            party.done();
            return;
        }
        Worker self = new Worker(worker);
        try {
            while (running) {
                self.step();
            }
        } catch (VirtualMachineError fatal) {
            faults.report(OffPathText.poolWorkerFatal(worker), fatal);
            stopAllRequest.run();
        } finally {
            party.done();
        }
    }

    /**
     * One worker's state between its steps: the batch it ran last and the shard it came from.
     * A step is a method of its own, called once a batch, rather than the body of the worker's
     * loop: the JIT compiles it as a whole method, which the workers of a monitor started later
     * (a bench's measured run after its warm-up) use from their first step. A loop's body is
     * compiled on the stack of the running loop, and that code is thrown away when the loop
     * ends with its monitor; a new monitor's workers then ran their first periods interpreted.
     */
    private final class Worker {
        private final int index;
        private final Shard own;
        private final int[] batch = new int[MAX_BATCH];
        /** deadlinesFrom[i]: the earliest deadline of batch[i..claimed-1] (what is left from cycle i on). */
        private final long[] deadlinesFrom = new long[MAX_BATCH];
        private Shard from;
        private int claimed;
        /** Whether it has run a batch since it last went to park: the recorder then has values to record. */
        private boolean ranSinceParking;

        Worker(int index) {
            this.index = index;
            this.own = shards[index];
            this.from = own;
        }

        /** Puts back the last batch, takes the next (its own shard's, else another's) and runs it, or parks. */
        void step() {
            if (claimed > 0 && from != own) {
                synchronized (from) {
                    putBack(from);
                    from.publishEarliest();
                }
                claimed = 0;
            }
            long now;
            synchronized (own) {
                putBack(own);
                now = clock.nanos();
                claimed = claim(own, now);
                own.publishEarliest();
            }
            from = own;
            for (int k = 1; k < shards.length && claimed == 0; k++) {
                Shard victim = shards[(index + k) % shards.length];
                if (victim.earliestNs <= now) {
                    synchronized (victim) {
                        claimed = claim(victim, clock.nanos());
                        victim.publishEarliest();
                    }
                    from = victim;
                }
            }
            if (claimed == 0) {
                if (ranSinceParking) {
                    ranSinceParking = false;
                    recorder.wake();
                }
                parkUntilDue(index, now);
                return;
            }
            ranSinceParking = true;
            wakeParkedWorker();
            long earliest = Long.MAX_VALUE;
            for (int i = claimed - 1; i >= 0; i--) {
                earliest = Math.min(earliest, releases.nextDeadlineNs(taskOf[batch[i]]));
                deadlinesFrom[i] = earliest;
            }
            int deadlineSlot = longSlot(index);
            long published = Long.MAX_VALUE;
            for (int i = 0; i < claimed && running; i++) {
                if (deadlinesFrom[i] != published) {
                    published = deadlinesFrom[i];
                    batchDeadlineNs.setRelease(deadlineSlot, published);
                }
                runCycle(index, pooled[batch[i]]);
            }
            batchDeadlineNs.setRelease(deadlineSlot, Long.MAX_VALUE);
        }

        /**
         * Puts the tasks of the last batch back into the shard they were claimed from, each keyed
         * by the release its runtime decided (none for a task that stopped). Holding the shard's lock.
         */
        private void putBack(Shard shard) {
            for (int i = 0; i < claimed; i++) {
                long next = releases.nextReleaseNs(taskOf[batch[i]]);
                if (next != TaskRuntime.NEVER) {
                    shard.waiting.push(batch[i], next);
                }
            }
        }

        /**
         * Takes up to {@link #MAX_BATCH} due releases of a shard, in run order, into the batch.
         * Holding the shard's lock.
         *
         * @return how many were taken
         */
        private int claim(Shard shard, long nowNs) {
            int taken = 0;
            TaskHeap waiting = shard.waiting;
            if (releaseOrderIsRunOrder) {
                while (taken < MAX_BATCH && waiting.peekKey() <= nowNs) {
                    batch[taken++] = waiting.pop();
                }
                return taken;
            }
            while (waiting.peekKey() <= nowNs) {
                int due = waiting.pop();
                shard.ready.push(due, readyKey(pooled[due]));
            }
            while (taken < MAX_BATCH && shard.ready.size() > 0) {
                batch[taken++] = shard.ready.pop();
            }
            return taken;
        }
    }


    /** @return the earliest release due in any shard ({@link Long#MIN_VALUE}: one is ready now) */
    private long earliestOfAllShards() {
        long earliest = Long.MAX_VALUE;
        for (Shard shard : shards) {
            earliest = Math.min(earliest, shard.earliestNs);
        }
        return earliest;
    }

    /**
     * Parks a worker that found nothing due until the earliest release of any shard (its own or
     * one it may steal from). It says so in {@link #parkedUntil} first and then looks at the
     * shards again: a worker that publishes an earlier release and then finds this one parked
     * past it wakes it ({@link #wakeParkedWorker}), so with both sides ordered no wake-up is lost.
     */
    private void parkUntilDue(int worker, long nowNs) {
        long until = earliestOfAllShards();
        if (until <= nowNs) {
            return;
        }
        parkedUntil.set(worker, until);
        if (earliestOfAllShards() < until) {
            parkedUntil.set(worker, NOT_PARKED);
            return;
        }
        workerParties[worker].park(until);
        parkedUntil.set(worker, NOT_PARKED);
    }

    /**
     * Called by a worker about to run a batch: wakes one parked worker that would otherwise
     * sleep past the earliest release of any shard, so that releases this worker cannot take
     * while it runs its batch are stolen in time. (The caller's own entry is not parked: a
     * worker clears it before its park returns.)
     */
    private void wakeParkedWorker() {
        long due = earliestOfAllShards();
        for (int w = 0; w < parkedUntil.length(); w++) {
            long until = parkedUntil.get(w);
            if (until != NOT_PARKED && due < until && parkedUntil.compareAndSet(w, until, NOT_PARKED)) {
                workerParties[w].wake();
                return;
            }
        }
    }

    /** @return the rate-monotonic rank among all tasks of the shortest-period pooled task (0 if none) */
    private int fastestPooledRank() {
        int[] ranks = ThreadedExecutor.rateMonotonicRanks(runtimes);
        int fastest = Integer.MAX_VALUE;
        for (TaskRuntime runtime : pooled) {
            fastest = Math.min(fastest, ranks[runtime.index()]);
        }
        return pooled.length == 0 ? 0 : fastest;
    }

    /**
     * Makes the workers, in order: named {@code rtaware-pool-<n>}, daemon, Java priority
     * {@code MAX_PRIORITY - 1}; each runs the {@link ThreadSetup} on itself (a fault is reported,
     * the worker runs on), counts down {@code ready}, then its loop. Used by {@link #start} only.
     */
    private final class WorkerThreadFactory implements ThreadFactory {
        private final int rmRank;
        private final CountDownLatch ready;
        private int next;

        WorkerThreadFactory(int rmRank, CountDownLatch ready) {
            this.rmRank = rmRank;
            this.ready = ready;
        }

        @Override
        public Thread newThread(Runnable loop) {
            int worker = next++;
            Thread thread = new Thread(() -> {
                try {
                    if (threadSetup != null) {
                        threadSetup.onPoolWorkerStart(worker, rmRank, runtimes.size());
                    }
                } catch (Throwable t) {
                    faults.report(OffPathText.poolWorkerSetup(worker), t);
                } finally {
                    ready.countDown();
                }
                loop.run();
            }, ThreadNames.poolWorker(worker));
            thread.setDaemon(true);
            thread.setPriority(Thread.MAX_PRIORITY - 1);
            return thread;
        }
    }

    /** @return whether every pooled task has the same relative deadline, which never changes */
    private boolean oneFixedDeadline() {
        long deadline = pooled.length == 0 ? -1 : pooled[0].fixedDeadlineNs();
        for (TaskRuntime runtime : pooled) {
            if (deadline < 0 || runtime.fixedDeadlineNs() != deadline) {
                return false;
            }
        }
        return true;
    }

    private long readyKey(TaskRuntime runtime) {
        return order == ExecutorKind.PoolOrder.RATE_MONOTONIC ? runtime.periodNs() : runtime.nextDeadlineNs();
    }

    private void runCycle(int worker, TaskRuntime runtime) {
        int slot = refSlot(worker);
        // An ordered store, not a volatile one: the cycle marks itself running (or missed) in its
        // deadline token, before the task's code, with a volatile store whose fence makes this
        // one visible before it; a second fence here only waited for the same stores.
        current.setRelease(slot, runtime);
        try {
            Executor.runCycle(runtime, clock, faults);
        } finally {
            // An ordered store: a watchdog that still sees the finished task finds its token done.
            current.setRelease(slot, null);
        }
    }

    /**
     * What the pool's watchdog looks at: a slot per worker, holding the cycle it runs now; the
     * deadline to wake for is the earliest of that cycle's and of the rest of the worker's batch.
     */
    private final class WorkerSlots implements Watchdog.Slots {
        @Override
        public int count() {
            return workers.length;
        }

        @Override
        public TaskRuntime taskAt(int worker) {
            return current.get(refSlot(worker));
        }

        @Override
        public long nextDeadlineNs(int worker, TaskRuntime task, long nowNs) {
            long earliest = Long.MAX_VALUE;
            if (task != null) {
                long deadline = task.runningDeadlineNs();
                if (deadline > nowNs) {
                    earliest = deadline;
                }
            }
            long batchDeadline = batchDeadlineNs.getAcquire(longSlot(worker));
            return batchDeadline > nowNs && batchDeadline < earliest ? batchDeadline : earliest;
        }
    }

    @Override
    public void stopReleasing() {
        running = false;
        for (Thread worker : workers) {
            if (worker != null) {
                LockSupport.unpark(worker);
            }
        }
        if (dedicated != null) {
            dedicated.stopReleasing();
        }
    }

    /** A pooled task may be on any worker: the workers are waited for if one of {@code tasks} is pooled. */
    @Override
    public void joinThreadsOf(Collection<TaskRuntime> tasks) {
        if (dedicated != null) {
            dedicated.joinThreadsOf(tasks);
        }
        if (tasks.stream().anyMatch(PooledExecutor::isPooled)) {
            for (Thread worker : workers) {
                Watchdog.joinOrInterrupt(worker, Watchdog.JOIN_TIMEOUT_MS, faults);
            }
        }
    }

    @Override
    public boolean runsCyclesOn(Thread thread) {
        return Arrays.asList(workers).contains(thread) || dedicated != null && dedicated.runsCyclesOn(thread);
    }

    @Override
    public void stopAndJoin() {
        stopReleasing();
        if (dedicated != null) {
            dedicated.stopWithoutClosing();
        }
        for (Thread worker : workers) {
            Watchdog.joinOrInterrupt(worker, Watchdog.JOIN_TIMEOUT_MS, faults);
        }
        watchdog.stopAndJoin();
        if (recorder != null) {
            recorder.stopAndJoin();
        }
        waiter.close();
    }
}
