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
 * A few worker threads release the periodic tasks that do not block from one timer structure,
 * in deadline order: for thousands of tasks, where a thread per task costs more than the work.
 * Continuous tasks, once tasks and tasks that {@link io.rtaware.core.task.Task#blocks() block}
 * keep a thread of their own, on an inner {@link ThreadedExecutor}.
 *
 * <p>The timer structure is two {@link TaskHeap}s under one lock: <em>waiting</em>, ordered by
 * next release, and <em>ready</em>, the releases already due, ordered by absolute deadline
 * (earliest deadline first) or by period (rate-monotonic). A worker, holding the lock, puts back
 * the tasks it has just run (keyed by the release each {@link TaskRuntime} decided), moves every
 * due release to ready, takes its share of the first ready tasks (at most {@link #MAX_BATCH}),
 * wakes a parked worker if work is left, and runs them outside the lock; with nothing ready it
 * parks with its {@link ClockWaiter} until the earliest waiting release. Under earliest deadline
 * first with one fixed relative deadline for every pooled task, release order is deadline order
 * and workers take due releases straight from the waiting heap (see
 * {@link #releaseOrderIsRunOrder}). The lock is the
 * happens-before edge between the workers that run one task's consecutive cycles. Every rule of
 * what a cycle means stays the runtime's: the same grid, misses, skips and counts as on the
 * threaded executor (a release that waited for a free worker is late, and one still waiting past
 * its next grid point is skipped by the same rule as after an overrun).
 *
 * <p>A watchdog thread reports misses at the deadline, as on the threaded executor, but it only
 * looks at the cycles the workers run now and the rest of their batches (one slot each per
 * worker), not at every task.
 *
 * <p>Each worker, the pool's watchdog and the inner executor's threads register with the one
 * {@link ClockWaiter} and wait and are woken through the {@link ClockWaiter.Party} they get.
 * Workers are made by a
 * {@link ThreadFactory} that runs {@link ThreadSetup#onPoolWorkerStart} on each before its first
 * release (with the rank of the shortest-period pooled task), and the start instant is taken
 * once every worker has run it; the tasks with their own thread run
 * {@link ThreadSetup#onTaskThreadStart}.
 *
 * <p>Steady state allocates nothing: heaps and slots are arrays sized at construction, the lock
 * is an object monitor. Thread-safe: started once, stopped once, by the monitor.
 */
final class PooledExecutor implements Executor {

    /**
     * Most due releases a worker takes at once (its share of the ready ones, in order): one lock
     * hold for up to this many cycles instead of one per cycle, which is what lets two workers
     * release 10 000 tasks at 100 Hz. A release claimed in a batch waits as it would in the
     * ready heap; a later release with an earlier deadline waits for at most this many cycles.
     */
    static final int MAX_BATCH = 32;

    private final Clock clock;
    private final ClockWaiter waiter;
    private final List<TaskRuntime> runtimes;
    private final ExecutorKind.PoolOrder order;
    private final Runnable stopAllRequest;
    private final FrameworkFaults faults;
    private final ThreadSetup threadSetup;
    /** The periodic tasks that do not block, by pool slot. */
    private final TaskRuntime[] pooled;
    /** The tasks with a thread of their own; null if there are none. */
    private final ThreadedExecutor dedicated;
    private final Watchdog watchdog;
    private final Thread[] workers;
    /** Each worker's handle in the waiter; set before the workers start. */
    private final ClockWaiter.Party[] workerParties;
    /** What each worker runs now (null: nothing); the watchdog scans these. */
    private final AtomicReferenceArray<TaskRuntime> current;
    /**
     * Per worker: the earliest deadline among the cycles of its batch not yet ended (the running
     * one included), {@link Long#MAX_VALUE} between batches. The watchdog sleeps until the
     * earliest of these, so a worker starting the next cycle of its batch finds it already due
     * to wake in time and does not wake it again: one wake per batch deadline, not one per cycle.
     */
    private final AtomicLongArray batchDeadlineNs;

    // The timer structure, guarded by the lock.
    private final Object lock = new Object();
    private final TaskHeap waiting;
    private final TaskHeap ready;
    /** Per worker: the world time it parks until, or {@link #NOT_PARKED}. */
    private final long[] parkedUntil;
    private static final long NOT_PARKED = Long.MIN_VALUE;

    /**
     * True when the waiting heap's order is already the order to run due releases in: earliest
     * deadline first, and every pooled task has the same fixed relative deadline, so release
     * order is deadline order (ties by slot in both). Workers then take due releases straight
     * from the waiting heap: no move to the ready heap, half the heap operations per release.
     * Set at start, under the lock.
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
        this.dedicated = own.isEmpty() ? null
                : new ThreadedExecutor(clock, waiter, own, stopAllRequest, threadSetup, faults);
        this.watchdog = new Watchdog(clock, waiter, faults, "pool watchdog", new WorkerSlots());
        this.workers = new Thread[workerCount];
        this.workerParties = new ClockWaiter.Party[workerCount];
        this.current = new AtomicReferenceArray<>(workerCount);
        this.batchDeadlineNs = new AtomicLongArray(workerCount);
        for (int w = 0; w < workerCount; w++) {
            batchDeadlineNs.set(w, Long.MAX_VALUE);
        }
        this.waiting = new TaskHeap(pooled.length);
        this.ready = new TaskHeap(pooled.length);
        this.parkedUntil = new long[workerCount];
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
            parkedUntil[w] = NOT_PARKED;
        }
        for (Thread worker : workers) {
            worker.start();
        }
        // As on the threaded executor: the start instant is taken once every worker has run its
        // thread setup, so the setup never makes release 0 late.
        ThreadedExecutor.awaitUninterruptibly(ready);
        long startNs = dedicated != null ? dedicated.start() : clock.nanos();
        synchronized (lock) {
            releaseOrderIsRunOrder = order == ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST && oneFixedDeadline();
            for (int slot = 0; slot < pooled.length; slot++) {
                TaskRuntime runtime = pooled[slot];
                runtime.watchedBy(watchdog);
                runtime.begin(startNs, stopAllRequest, waiter.zeroCycleSpacingNs());
                waiting.push(slot, runtime.nextReleaseNs());
            }
        }
        watchdog.start();
        go.countDown();
        return startNs;
    }

    private void work(int worker, CountDownLatch go) {
        ClockWaiter.Party party = workerParties[worker];
        try {
            go.await();
        } catch (InterruptedException e) {
            party.done();
            return;
        }
        int[] batch = new int[MAX_BATCH];
        // deadlinesFrom[i]: the earliest deadline of batch[i..claimed-1] (what is left from cycle i on).
        long[] deadlinesFrom = new long[MAX_BATCH];
        int claimed = 0;
        try {
            while (running) {
                long parkUntilNs = 0;
                synchronized (lock) {
                    for (int i = 0; i < claimed; i++) {
                        long next = pooled[batch[i]].nextReleaseNs();
                        if (next != TaskRuntime.NEVER) {
                            waiting.push(batch[i], next);
                        }
                    }
                    claimed = 0;
                    long now = clock.nanos();
                    if (releaseOrderIsRunOrder) {
                        // How many are due is not known without popping: take one if another
                        // worker is parked (it is woken for the rest), else up to a batch.
                        int share = anotherWorkerParked(worker) ? 1 : MAX_BATCH;
                        while (claimed < share && waiting.size() > 0 && waiting.peekKey() <= now) {
                            batch[claimed++] = waiting.pop();
                        }
                    } else {
                        while (waiting.size() > 0 && waiting.peekKey() <= now) {
                            int due = waiting.pop();
                            ready.push(due, readyKey(pooled[due]));
                        }
                        int share = Math.min(MAX_BATCH, Math.max(1, ready.size() / workers.length));
                        while (claimed < share && ready.size() > 0) {
                            batch[claimed++] = ready.pop();
                        }
                    }
                    if (claimed > 0) {
                        parkedUntil[worker] = NOT_PARKED;
                        wakeParkedWorker(ready.size() > 0 ? Long.MAX_VALUE : waiting.peekKey());
                    } else {
                        parkUntilNs = waiting.peekKey();
                        parkedUntil[worker] = parkUntilNs;
                    }
                }
                if (claimed == 0) {
                    party.park(parkUntilNs);
                    continue;
                }
                long earliest = Long.MAX_VALUE;
                for (int i = claimed - 1; i >= 0; i--) {
                    earliest = Math.min(earliest, pooled[batch[i]].nextDeadlineNs());
                    deadlinesFrom[i] = earliest;
                }
                for (int i = 0; i < claimed && running; i++) {
                    batchDeadlineNs.setRelease(worker, deadlinesFrom[i]);
                    runCycle(worker, pooled[batch[i]]);
                }
                batchDeadlineNs.setRelease(worker, Long.MAX_VALUE);
            }
        } catch (VirtualMachineError fatal) {
            faults.report("pool worker " + worker + " (fatal VM error: stopping every task)", fatal);
            stopAllRequest.run();
        } finally {
            party.done();
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
                    faults.report("thread setup of pool worker " + worker, t);
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

    /** @return whether a worker other than {@code worker} is parked; holding the lock */
    private boolean anotherWorkerParked(int worker) {
        for (int w = 0; w < parkedUntil.length; w++) {
            if (w != worker && parkedUntil[w] != NOT_PARKED) {
                return true;
            }
        }
        return false;
    }

    /**
     * Wakes one parked worker that would otherwise sleep past {@code dueNs} (work that another
     * worker could take now, or an earlier release than it waits for). Holding the lock.
     */
    private void wakeParkedWorker(long dueNs) {
        for (int w = 0; w < parkedUntil.length; w++) {
            long until = parkedUntil[w];
            if (until != NOT_PARKED && (dueNs == Long.MAX_VALUE || dueNs < until)) {
                parkedUntil[w] = NOT_PARKED;
                workerParties[w].wake();
                return;
            }
        }
    }

    private long readyKey(TaskRuntime runtime) {
        return order == ExecutorKind.PoolOrder.RATE_MONOTONIC ? runtime.periodNs() : runtime.nextDeadlineNs();
    }

    private void runCycle(int worker, TaskRuntime runtime) {
        current.set(worker, runtime);
        try {
            Executor.runCycle(runtime, clock, faults);
        } finally {
            // An ordered store: a watchdog that still sees the finished task finds its token done.
            current.setRelease(worker, null);
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
            return current.get(worker);
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
            long batchDeadline = batchDeadlineNs.getAcquire(worker);
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
        waiter.close();
    }
}
