package io.rtaware.rt;

import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.monitor.ThreadSetup;
import java.io.PrintStream;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * {@code --realtime}: a {@link ThreadSetup} that makes each task thread SCHED_FIFO with a
 * rate-monotonic priority ({@code topPriority} for the shortest period, one less per rank, at
 * least 1; each worker of the pooled executor gets the priority of the fastest task it runs),
 * pins a task's thread to a CPU if asked, and sets its timer slack to 1 ns (which needs no
 * privilege and cuts the median wake-up lateness from ~70 to ~20 us). The executors' watchdogs,
 * which report misses at their deadlines, are SCHED_FIFO one above the top priority
 * ({@link #watchdogPriority()}), with 1 ns slack: at a task's priority or below, a watchdog
 * could not run while the task threads keep every CPU busy, and a miss would be reported only
 * when its cycle returned. The JVM's own threads (the JIT compilers and the collector's among
 * them) stay SCHED_OTHER.
 *
 * <p>{@link #configure} first probes on a short-lived thread whether the process may use
 * SCHED_FIFO (root, CAP_SYS_NICE or a large enough RLIMIT_RTPRIO); if it may not, or this is
 * not Linux, it prints one line saying so and the run goes on with normal threads (still with
 * 1 ns timer slack and the requested affinity when those work). Thread-safe.
 */
public final class RealtimeThreads implements ThreadSetup {

    /** Default SCHED_FIFO priority of the highest-rate task. */
    public static final int DEFAULT_TOP_PRIORITY = 80;
    private static final int EPERM = 1;

    private final LinuxSched sched;
    private final boolean fifo;
    private final int topPriority;
    private final Map<String, Integer> cpuByTask;
    private final PrintStream err;
    private final AtomicInteger fifoThreads = new AtomicInteger();
    private final AtomicBoolean warned = new AtomicBoolean();

    private RealtimeThreads(LinuxSched sched, boolean fifo, int topPriority, Map<String, Integer> cpuByTask,
                            PrintStream err) {
        this.sched = sched;
        this.fifo = fifo;
        this.topPriority = topPriority;
        this.cpuByTask = Map.copyOf(cpuByTask);
        this.err = err;
    }

    /**
     * The one call a command needs for {@code --realtime}.
     *
     * @param topPriority SCHED_FIFO priority of the shortest-period task, 2..99
     * @param cpuByTask CPU to pin each named task's thread to (tasks not named are not pinned)
     * @param err where the single fallback line goes
     * @return the hook to pass to {@code Monitor.Builder#threadSetup}, or null when native
     *     access is impossible (no JNA on the class path, not Linux, no libc): then normal
     *     threads are used
     */
    public static RealtimeThreads configure(int topPriority, Map<String, Integer> cpuByTask, PrintStream err) {
        Optional<String> noJna = Jna.missingReason();
        if (noJna.isPresent()) {
            err.println("rtaware: --realtime unavailable (" + noJna.get() + "); running with normal threads");
            return null;
        }
        LinuxSched sched;
        try {
            sched = JnaLinuxSched.load();
        } catch (UnsupportedOperationException e) {
            err.println("rtaware: --realtime unavailable (" + e.getMessage() + "); running with normal threads");
            return null;
        }
        return configure(sched, topPriority, cpuByTask, err);
    }

    /**
     * As {@link #configure(int, Map, PrintStream)} with a given native binding (tests use a
     * fake one).
     *
     * @param sched the native calls
     * @param topPriority SCHED_FIFO priority of the shortest-period task, 2..99
     * @param cpuByTask CPU per task name
     * @param err where the single fallback line goes
     * @return the hook; SCHED_FIFO only if the probe succeeded
     */
    public static RealtimeThreads configure(LinuxSched sched, int topPriority, Map<String, Integer> cpuByTask,
                                            PrintStream err) {
        if (topPriority < 2 || topPriority > 99) {
            throw new IllegalArgumentException("SCHED_FIFO priority must be 2..99, got " + topPriority);
        }
        int[] result = new int[1];
        Thread probe = new Thread(() -> result[0] = sched.setFifo(1), "rtaware-rt-probe");
        probe.start();
        try {
            probe.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            result[0] = -1;
        }
        boolean fifo = result[0] == 0;
        if (!fifo) {
            err.println("rtaware: --realtime: SCHED_FIFO not permitted (" + errno(result[0])
                    + "; needs root, CAP_SYS_NICE or ulimit -r >= " + topPriority
                    + "); running with normal threads, timer slack 1 ns");
        }
        return new RealtimeThreads(sched, fifo, topPriority, cpuByTask, err);
    }

    private static String errno(int e) {
        return e == EPERM ? "EPERM" : "errno " + e;
    }

    /** @return true if task threads are made SCHED_FIFO */
    public boolean fifo() {
        return fifo;
    }

    /** @return how many task threads, pool workers and watchdogs are SCHED_FIFO so far */
    public int fifoThreads() {
        return fifoThreads.get();
    }

    /**
     * @param rmRank a rate-monotonic rank (0 for the shortest period)
     * @return the SCHED_FIFO priority of that rank
     */
    public int priorityOf(int rmRank) {
        return Math.max(1, topPriority - rmRank);
    }

    /**
     * @return the SCHED_FIFO priority of the watchdogs: one above the top task priority, at most
     *     99 (at 99 the watchdog shares the top tasks' priority, and runs when one of them yields
     *     the CPU)
     */
    public int watchdogPriority() {
        return Math.min(99, topPriority + 1);
    }

    @Override
    public void onTaskThreadStart(TaskInfo task, int rmRank, int taskCount) {
        sched.timerSlack(MinimalTimerSlack.SLACK_NS);
        Integer cpu = cpuByTask.get(task.name());
        if (cpu != null) {
            int e = sched.pinTo(cpu);
            if (e != 0) {
                warnOnce("could not pin task '" + task.name() + "' to CPU " + cpu + " (" + errno(e) + ")");
            }
        }
        fifoAt(priorityOf(rmRank), "task '" + task.name() + "'");
    }

    /**
     * A pool worker runs releases of every pooled task: it gets the SCHED_FIFO priority of the
     * most urgent of them and 1 ns timer slack, and is pinned nowhere (CPUs are asked per task).
     */
    @Override
    public void onPoolWorkerStart(int worker, int rmRank, int taskCount) {
        sched.timerSlack(MinimalTimerSlack.SLACK_NS);
        fifoAt(priorityOf(rmRank), "pool worker " + worker);
    }

    /**
     * A watchdog runs a few microseconds at each deadline it watches: it gets the SCHED_FIFO
     * priority above every task's ({@link #watchdogPriority()}) and 1 ns timer slack, so that it
     * reports a miss at the deadline even while the tasks keep every CPU busy.
     */
    @Override
    public void onWatchdogStart(int taskCount) {
        sched.timerSlack(MinimalTimerSlack.SLACK_NS);
        fifoAt(watchdogPriority(), "the watchdog");
    }

    /**
     * Makes the calling thread SCHED_FIFO at {@code priority} if the probe found it permitted,
     * and counts it; a refusal is warned about once.
     *
     * @param priority 1..99
     * @param thread what the warning calls the thread
     */
    private void fifoAt(int priority, String thread) {
        if (!fifo) {
            return;
        }
        int e = sched.setFifo(priority);
        if (e == 0) {
            fifoThreads.incrementAndGet();
        } else {
            warnOnce(thread + " stays SCHED_OTHER (" + errno(e) + ")");
        }
    }

    private void warnOnce(String message) {
        if (warned.compareAndSet(false, true)) {
            err.println("rtaware: --realtime: " + message);
        }
    }
}
