package io.rtaware.core.monitor;

import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.time.Clock;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.locks.LockSupport;

/**
 * One named platform thread per task, as in the paper, plus a watchdog thread that reports
 * deadline misses at the deadline. Each task thread only waits and calls (see {@link Executor}):
 * it waits with its {@link ClockWaiter} until the task's next release, runs the cycle, and
 * repeats; every rule of what a cycle means is the {@link TaskRuntime}'s.
 *
 * <p>Task threads get rate-monotonic Java priorities as a hint to the JVM (shorter period,
 * higher priority: rank 0 gets {@code MAX_PRIORITY - 1}, down to {@code NORM_PRIORITY}; tasks
 * without a period get {@code NORM_PRIORITY}; the watchdog has {@code MAX_PRIORITY}). An
 * optional {@link ThreadSetup} runs on each task thread before its first release.
 *
 * <p>No fault of the framework stops a task thread or the watchdog: listener faults are
 * contained by the runtime, anything else thrown around a cycle or in the watchdog's scan is
 * reported to the {@link FrameworkFaults} and the loop goes on. Only a
 * {@link VirtualMachineError} of a task stops the monitor.
 *
 * <p>Thread-safe: started once, stopped once, by the monitor.
 */
final class ThreadedExecutor implements Executor {

    private final Clock clock;
    private final ClockWaiter waiter;
    private final List<TaskRuntime> runtimes;
    /** The same tasks as an array: the watchdog loops over it on every wake without an iterator. */
    private final TaskRuntime[] watched;
    private final Runnable stopAllRequest;
    private final ThreadSetup threadSetup;
    private final FrameworkFaults faults;
    private final Watchdog watchdog;
    private final List<Thread> threads = new ArrayList<>();
    /** Each task thread's handle in the waiter, by the thread's slot in {@link #threads}; filled before they start. */
    private final List<ClockWaiter.Party> parties = new ArrayList<>();
    private volatile boolean running;

    /**
     * @param runtimes the tasks it runs: all of the monitor's, or (inside a pool) those that keep
     *     a thread of their own
     */
    ThreadedExecutor(Clock clock, ClockWaiter waiter, List<TaskRuntime> runtimes, Runnable stopAllRequest,
                     ThreadSetup threadSetup, FrameworkFaults faults) {
        this.clock = clock;
        this.waiter = waiter;
        this.runtimes = runtimes;
        this.watched = runtimes.toArray(new TaskRuntime[0]);
        this.stopAllRequest = stopAllRequest;
        this.threadSetup = threadSetup;
        this.faults = faults;
        this.watchdog = new Watchdog(clock, waiter, faults, "watchdog", new TaskSlots(), threadSetup,
                runtimes.size());
    }

    /** @return its watchdog */
    Watchdog watchdog() {
        return watchdog;
    }

    /** @return the waiter its threads wait with (tests on a manual clock step through it) */
    ClockWaiter waiter() {
        return waiter;
    }

    /**
     * @param runtimes the tasks
     * @return each task's rate-monotonic rank among them, by task index (see {@link ThreadSetup})
     */
    static int[] rateMonotonicRanks(List<TaskRuntime> runtimes) {
        List<TaskRuntime> order = new ArrayList<>(runtimes);
        // Stable sort: equal periods keep registration order; tasks without a period go last.
        order.sort(Comparator.comparingLong(r -> r.isPeriodic() ? r.periodNs() : Long.MAX_VALUE));
        int[] ranks = new int[runtimes.stream().mapToInt(TaskRuntime::index).max().orElse(-1) + 1];
        for (int rank = 0; rank < order.size(); rank++) {
            ranks[order.get(rank).index()] = rank;
        }
        return ranks;
    }

    @Override
    public long start() {
        running = true;
        CountDownLatch ready = new CountDownLatch(runtimes.size());
        CountDownLatch go = new CountDownLatch(1);
        watchdog.prepare();
        int[] ranks = rateMonotonicRanks(runtimes);
        for (TaskRuntime runtime : runtimes) {
            runtime.watchedBy(watchdog);
            runtime.prepareStart(stopAllRequest, waiter.zeroCycleSpacingNs());
            int rank = ranks[runtime.index()];
            int slot = threads.size();
            Thread thread = new Thread(() -> runTask(runtime, parties.get(slot), rank, ready, go),
                    ThreadNames.task(runtime.name()));
            thread.setDaemon(true);
            thread.setPriority(runtime.isPeriodic()
                    ? Math.max(Thread.NORM_PRIORITY, Thread.MAX_PRIORITY - 1 - rank) : Thread.NORM_PRIORITY);
            parties.add(waiter.register(thread));
            threads.add(thread);
        }
        threads.forEach(Thread::start);
        // The start instant is taken once every task thread exists and has run its thread setup,
        // so thread creation never makes release 0 late.
        awaitUninterruptibly(ready);
        long startNs = clock.nanos();
        for (TaskRuntime runtime : runtimes) {
            runtime.begin(startNs);
        }
        watchdog.start();
        go.countDown();
        return startNs;
    }

    /** Waits for the latch, keeping an interrupt for later. */
    static void awaitUninterruptibly(CountDownLatch latch) {
        boolean interrupted = false;
        while (true) {
            try {
                latch.await();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    private void runTask(TaskRuntime runtime, ClockWaiter.Party party, int rank, CountDownLatch ready,
                         CountDownLatch go) {
        try {
            if (threadSetup != null) {
                threadSetup.onTaskThreadStart(runtime, rank, runtimes.size());
            }
        } catch (Throwable t) {
            faults.report(OffPathText.taskThreadSetup(runtime.name()), t);
        } finally {
            ready.countDown();
        }
        awaitUninterruptibly(go);
        try {
            while (running) {
                long due = runtime.nextReleaseNs();
                if (due == TaskRuntime.NEVER || !waitUntil(party, due)) {
                    return;
                }
                Executor.runCycle(runtime, clock, faults);
            }
        } catch (VirtualMachineError fatal) {
            faults.report(OffPathText.taskThreadFatal(runtime.name()), fatal);
            stopAllRequest.run();
        } finally {
            party.done();
        }
    }

    /** Waits until the world clock reaches {@code targetNs}; false if stopped meanwhile. */
    private boolean waitUntil(ClockWaiter.Party party, long targetNs) {
        while (running) {
            if (clock.nanos() >= targetNs) {
                return true;
            }
            // Nothing wakes a task thread but its release: it may sleep without being unparkable.
            party.sleep(targetNs);
        }
        return false;
    }

    /**
     * What the watchdog looks at: a slot per task; the deadline to wake for is that of the
     * running cycle or of the release an idle task waits for. Tasks released on time never wake
     * the watchdog, so tasks sharing a period cost one scan per period, not one per cycle start.
     */
    private final class TaskSlots implements Watchdog.Slots {
        @Override
        public int count() {
            return watched.length;
        }

        @Override
        public TaskRuntime taskAt(int slot) {
            return watched[slot];
        }

        @Override
        public long nextDeadlineNs(int slot, TaskRuntime task, long nowNs) {
            long deadline = task.watchDeadlineNs();
            // A deadline already past belongs to a task between cycles, about to publish its next.
            return deadline > nowNs ? deadline : Long.MAX_VALUE;
        }
    }

    @Override
    public void stopAndJoin() {
        stopWithoutClosing();
        waiter.close();
    }

    @Override
    public void stopReleasing() {
        running = false;
        threads.forEach(LockSupport::unpark);
    }

    @Override
    public void joinThreadsOf(Collection<TaskRuntime> tasks) {
        for (int slot = 0; slot < threads.size(); slot++) {
            if (tasks.contains(runtimes.get(slot))) {
                Watchdog.joinOrInterrupt(threads.get(slot), Watchdog.JOIN_TIMEOUT_MS, faults);
            }
        }
    }

    @Override
    public boolean runsCyclesOn(Thread thread) {
        return threads.contains(thread);
    }

    /** Stops and joins the threads, leaving the waiter open (a pool that holds this one closes it). */
    void stopWithoutClosing() {
        stopReleasing();
        for (Thread thread : threads) {
            Watchdog.joinOrInterrupt(thread, Watchdog.JOIN_TIMEOUT_MS, faults);
        }
        watchdog.stopAndJoin();
    }
}
