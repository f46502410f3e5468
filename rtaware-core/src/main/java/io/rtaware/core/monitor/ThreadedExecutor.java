package io.rtaware.core.monitor;

import io.rtaware.core.time.Clock;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * One named platform thread per task, as in the paper, plus a watchdog thread that reports
 * deadline misses at the deadline. Periodic tasks wait for their absolute release time with
 * {@link LockSupport#parkNanos} (never {@code Thread.sleep}, which rounds to whole
 * milliseconds on JDK 17); lateness is measured against the scheduled release.
 *
 * <p>Task threads get rate-monotonic Java priorities as a hint to the JVM (shorter period,
 * higher priority: rank 0 gets {@code MAX_PRIORITY - 1}, down to {@code NORM_PRIORITY}; tasks
 * without a period get {@code NORM_PRIORITY}; the watchdog has {@code MAX_PRIORITY}). An
 * optional {@link ThreadSetup} runs on each task thread before its first release.
 *
 * <p>A continuous task whose cycle throws is released again only after
 * {@value #CONTINUOUS_ERROR_PAUSE_NS} ns of wall time, so a failing input cannot spin a core.
 *
 * <p>Thread-safe: started once, stopped once, by the monitor.
 */
final class ThreadedExecutor implements Monitor.Executor {

    private static final long JOIN_TIMEOUT_MS = 5_000;
    /** Wall time a continuous task waits after a cycle that threw, before it is released again. */
    static final long CONTINUOUS_ERROR_PAUSE_NS = 20_000_000L;

    private final Clock clock;
    private final List<TaskRuntime> runtimes;
    /** The same tasks as an array: the watchdog loops over it on every wake without an iterator. */
    private final TaskRuntime[] watched;
    private final Runnable stopAllRequest;
    private final ThreadSetup threadSetup;
    private final List<Thread> threads = new ArrayList<>();
    private volatile boolean running;
    private Thread watchdog;
    /** The world time the watchdog sleeps until; task threads wake it for an earlier deadline. */
    private volatile long watchdogWakeNs = Long.MAX_VALUE;

    ThreadedExecutor(Clock clock, List<TaskRuntime> runtimes, Runnable stopAllRequest, ThreadSetup threadSetup) {
        this.clock = clock;
        this.runtimes = runtimes;
        this.watched = runtimes.toArray(new TaskRuntime[0]);
        this.stopAllRequest = stopAllRequest;
        this.threadSetup = threadSetup;
    }

    /**
     * @param runtimes the tasks
     * @return each task's rate-monotonic rank by task index (see {@link ThreadSetup})
     */
    static int[] rateMonotonicRanks(List<TaskRuntime> runtimes) {
        List<TaskRuntime> order = new ArrayList<>(runtimes);
        // Stable sort: equal periods keep registration order; tasks without a period go last.
        order.sort(java.util.Comparator.comparingLong(r -> r.isPeriodic() ? r.periodNs() : Long.MAX_VALUE));
        int[] ranks = new int[runtimes.size()];
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
        watchdog = new Thread(this::watch, "rtaware-monitor");
        watchdog.setDaemon(true);
        watchdog.setPriority(Thread.MAX_PRIORITY);
        int[] ranks = rateMonotonicRanks(runtimes);
        for (TaskRuntime runtime : runtimes) {
            runtime.onCycleStart(() -> wakeWatchdogFor(runtime));
            int rank = ranks[runtime.index()];
            Thread thread = new Thread(() -> runTask(runtime, rank, ready, go), "rtaware-" + runtime.name());
            thread.setDaemon(true);
            thread.setPriority(runtime.isPeriodic()
                    ? Math.max(Thread.NORM_PRIORITY, Thread.MAX_PRIORITY - 1 - rank) : Thread.NORM_PRIORITY);
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

    private static void awaitUninterruptibly(CountDownLatch latch) {
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

    private void runTask(TaskRuntime runtime, int rank, CountDownLatch ready, CountDownLatch go) {
        try {
            if (threadSetup != null) {
                threadSetup.onTaskThreadStart(runtime, rank, runtimes.size());
            }
        } catch (RuntimeException e) {
            System.err.println("rtaware: thread setup failed for task '" + runtime.name() + "': " + e);
        } finally {
            ready.countDown();
        }
        awaitUninterruptibly(go);
        try {
            switch (runtime.schedule().kind()) {
                case "periodic" -> runPeriodic(runtime);
                case "continuous" -> runContinuous(runtime);
                default -> runOnce(runtime);
            }
        } catch (VirtualMachineError fatal) {
            System.err.println("rtaware: task '" + runtime.name() + "' hit a fatal VM error: " + fatal);
            stopAllRequest.run();
        }
    }

    private void runPeriodic(TaskRuntime runtime) {
        long k = 0;
        while (running) {
            long releaseNs = runtime.releaseTimeNs(k);
            runtime.pending(k);
            if (!waitUntil(releaseNs)) {
                return;
            }
            TaskRuntime.Outcome outcome = runtime.runCycle(k, releaseNs);
            if (!handle(runtime, outcome)) {
                return;
            }
            k = runtime.nextIndexAfter(k, runtime.lastCycleEndNs());
        }
    }

    private void runContinuous(TaskRuntime runtime) {
        long k = 0;
        while (running) {
            TaskRuntime.Outcome outcome = runtime.runCycle(k++, clock.nanos());
            if (!handle(runtime, outcome)) {
                return;
            }
            if (runtime.lastCycleFailed()) {
                // A continuous task that keeps throwing (a lost connection, say) would otherwise
                // spin a core and flood the error count; each failure pauses it briefly.
                LockSupport.parkNanos(CONTINUOUS_ERROR_PAUSE_NS);
            }
        }
    }

    private void runOnce(TaskRuntime runtime) {
        long releaseNs = runtime.releaseTimeNs(0);
        if (waitUntil(releaseNs) && handle(runtime, runtime.runCycle(0, releaseNs))) {
            runtime.setState(TaskState.FINISHED, clock.nanos());
        }
    }

    /**
     * Runs on the task thread after its cycle is marked running. The cycle must be visible to the
     * watchdog before the wake time is read: then either the watchdog's re-check sees the cycle,
     * or this thread sees the watchdog's new wake time and unparks it if its deadline is earlier.
     */
    private void wakeWatchdogFor(TaskRuntime runtime) {
        if (runtime.runningDeadlineNs() < watchdogWakeNs) {
            LockSupport.unpark(watchdog);
        }
    }

    /** @return true if the task goes on */
    private boolean handle(TaskRuntime runtime, TaskRuntime.Outcome outcome) {
        switch (outcome) {
            case DISABLE -> {
                runtime.setState(TaskState.DISABLED, clock.nanos());
                return false;
            }
            case STOP_ALL -> {
                stopAllRequest.run();
                return false;
            }
            default -> {
                return true;
            }
        }
    }

    /** Parks until the world clock reaches {@code targetNs}; false if stopped meanwhile. */
    private boolean waitUntil(long targetNs) {
        while (running) {
            long remainingNs = targetNs - clock.nanos();
            if (remainingNs <= 0) {
                return true;
            }
            LockSupport.parkNanos(clock.toWallNanos(remainingNs));
        }
        return false;
    }

    /**
     * Sleeps until the earliest deadline any periodic task could miss (of a running cycle, or of
     * the release an idle task waits for), then claims the misses of cycles still running past
     * their deadline. Tasks released on time never wake it, so tasks sharing a period cost one
     * scan per period, not one per cycle start.
     */
    private void watch() {
        while (running) {
            long now = clock.nanos();
            long earliest = Long.MAX_VALUE;
            for (TaskRuntime runtime : watched) {
                runtime.checkDeadline(now);
                long deadline = runtime.pendingDeadlineNs();
                // A deadline already past belongs to a task between cycles, about to publish its next.
                if (deadline > now && deadline < earliest) {
                    earliest = deadline;
                }
            }
            watchdogWakeNs = earliest;
            long remaining = earliest == Long.MAX_VALUE ? TimeUnit.MILLISECONDS.toNanos(100)
                    : clock.toWallNanos(earliest - clock.nanos()) + 1_000;
            if (remaining > 0) {
                // Wake just after the deadline: a miss is a cycle still running past it.
                LockSupport.parkNanos(remaining);
            }
        }
    }

    @Override
    public void stopAndJoin() {
        running = false;
        threads.forEach(LockSupport::unpark);
        if (watchdog != null) {
            LockSupport.unpark(watchdog);
        }
        for (Thread thread : threads) {
            if (thread == Thread.currentThread()) {
                continue;
            }
            try {
                thread.join(JOIN_TIMEOUT_MS);
                if (thread.isAlive()) {
                    System.err.println("rtaware: " + thread.getName() + " did not return within "
                            + JOIN_TIMEOUT_MS + " ms of stop; interrupting it");
                    thread.interrupt();
                    thread.join(JOIN_TIMEOUT_MS);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
        try {
            if (watchdog != null) {
                watchdog.join(JOIN_TIMEOUT_MS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
