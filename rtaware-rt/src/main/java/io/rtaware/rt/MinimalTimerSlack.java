package io.rtaware.rt;

import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.monitor.ThreadSetup;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A {@link ThreadSetup} that asks the kernel for the smallest timer slack on every thread that
 * runs cycles, and on the watchdogs ({@code prctl(PR_SET_TIMERSLACK, 1)}). Linux lets a timer of a normally scheduled
 * thread expire up to its slack late, 50 us by default, so that it can batch wake-ups: every
 * release of a task parked in {@code parkNanos} or {@code clock_nanosleep} would otherwise start
 * up to 50 us late for no reason of the task's own. Threads under SCHED_FIFO have no slack, so
 * {@code --realtime} ({@link RealtimeThreads}) asks for the same on the threads it could not make
 * real-time. Asking is unprivileged; a thread that cannot change its slack keeps the kernel's
 * and runs on. What each thread got is in the run's conditions ({@code timer_slack_ns}).
 *
 * <p>Use it from your own {@code main}:
 * {@code Monitor.builder(clock).threadSetup(MinimalTimerSlack.load().orElse(null))}.
 */
public final class MinimalTimerSlack implements ThreadSetup {

    /** The slack asked for, ns: the kernel's smallest (0 would mean "the default"). */
    public static final long SLACK_NS = 1;

    private final LinuxSched sched;
    private final AtomicInteger refused = new AtomicInteger();

    /**
     * @param sched the system calls
     */
    public MinimalTimerSlack(LinuxSched sched) {
        this.sched = sched;
    }

    /**
     * @return the setup, or empty where it cannot work (not Linux, or JNA cannot load libc): the
     *     threads then keep the kernel's slack
     */
    public static Optional<ThreadSetup> load() {
        if (Jna.missingReason().isPresent()) {
            return Optional.empty();
        }
        try {
            return Optional.of(new MinimalTimerSlack(JnaLinuxSched.load()));
        } catch (UnsupportedOperationException e) {
            return Optional.empty();
        }
    }

    @Override
    public void onTaskThreadStart(TaskInfo task, int rmRank, int taskCount) {
        ask();
    }

    @Override
    public void onPoolWorkerStart(int worker, int rmRank, int taskCount) {
        ask();
    }

    /** The watchdog too: it wakes at the deadlines it watches, and reports a miss that much later. */
    @Override
    public void onWatchdogStart(int taskCount) {
        ask();
    }

    private void ask() {
        if (sched.timerSlack(SLACK_NS) != 0) {
            refused.incrementAndGet();
        }
    }

    /** @return the threads whose request the kernel refused (they keep its default slack) */
    public int refused() {
        return refused.get();
    }
}
