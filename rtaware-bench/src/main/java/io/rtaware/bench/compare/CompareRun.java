package io.rtaware.bench.compare;

import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import io.rtaware.core.monitor.ExecutorKind;
import io.rtaware.core.monitor.ThreadSetup;
import io.rtaware.core.testing.ThreadAllocation;
import io.rtaware.core.time.MonotonicSleeper;
import java.io.PrintStream;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.locks.LockSupport;
import java.util.stream.Collectors;

/**
 * Runs the same task set on rtaware, on {@code ScheduledThreadPoolExecutor}, on a bare
 * parkNanos loop and on the timer wheels of Netty and Agrona, <b>interleaved in segments</b>: round r runs one segment of each executor, in
 * an order rotated by r, so every executor sees the same machine noise (on a shared host, back
 * to back runs of a minute differ by up to 10x in the tail). Round 0 is a warm-up (JIT) and is
 * not counted. Each segment starts fresh threads; the {@link #settleNs} after its executor's
 * start has returned are not counted (thread start-up, first releases), and its measurement
 * window is {@code [started + settle, started + segment)}.
 * CPU time ({@code com.sun.management.ThreadMXBean}) and allocation ({@link ThreadAllocation}) of the
 * executor's threads are read at both ends of the window.
 *
 * <p>Not thread-safe: one thread runs the comparison.
 */
public final class CompareRun {

    private final List<BenchSpec> specs;
    private final BusyWork work;
    private final long segmentNs;
    private final long settleNs;
    private final int rounds;
    private final PrintStream progress;
    private final com.sun.management.ThreadMXBean threads;
    private final List<String> rows;
    private final List<String> leftOut;
    private final int workers;
    private final MonotonicSleeper sleeper;
    private final ThreadSetup threadSetup;

    /**
     * Most tasks per core for which the executors with a thread per task run. Beyond, their
     * threads outnumber what the cores can wake at the tasks' rates: measured here (2 cores),
     * 10 000 tasks at 100 Hz drove the load average past 2000 and the park loop's warm-up segment
     * had not ended after 9 minutes, taking the machine from everything else on it.
     */
    static final int THREAD_PER_TASK_LIMIT_PER_CORE = 1000;

    /**
     * @param tasks a task count
     * @return whether the executors with a thread per task run for it on this machine
     */
    static boolean threadPerTaskFits(int tasks) {
        return tasks <= (long) THREAD_PER_TASK_LIMIT_PER_CORE * Runtime.getRuntime().availableProcessors();
    }

    /** Every row a comparison can run, by its executor label, in the table's order. */
    public static final List<String> ROWS = List.of("rtaware", "rtaware-pooled", "stpe", "stpe-pooled", "park-loop",
            "netty-wheel", "agrona-wheel");

    /** The rows with a thread per task, left out beyond {@link #THREAD_PER_TASK_LIMIT_PER_CORE}. */
    public static final Set<String> THREAD_PER_TASK_ROWS = Set.of("rtaware", "stpe", "park-loop");

    /** The sets of rows {@code bench --executor} names; each has the park loop, the floor. */
    public enum Family {
        /** Every row. */
        ALL(ROWS),
        /** rtaware threaded and STPE with a thread per task. */
        THREADED(List.of("rtaware", "stpe", "park-loop")),
        /**
         * rtaware pooled, STPE with one pool of the same size, and the timer wheels (one thread
         * each, for many timers).
         */
        POOLED(List.of("rtaware-pooled", "stpe-pooled", "park-loop", "netty-wheel", "agrona-wheel"));

        private final List<String> rows;

        Family(List<String> rows) {
            this.rows = rows;
        }

        /** @return the family's rows, in the table's order */
        public List<String> rows() {
            return rows;
        }
    }

    /**
     * Reads a list of row labels, as {@code bench --compare --executor netty-wheel,agrona-wheel} gives it.
     *
     * @param labels labels of {@link #ROWS}, comma-separated
     * @return them in the table's order, each once
     * @throws IllegalArgumentException naming the first label that is not a row
     */
    public static List<String> rows(String labels) {
        Set<String> wanted = new java.util.HashSet<>();
        for (String label : labels.split(",", -1)) {
            if (!ROWS.contains(label.strip())) {
                throw new IllegalArgumentException("no comparison row '" + label.strip() + "'; rows: "
                        + String.join(", ", ROWS));
            }
            wanted.add(label.strip());
        }
        return ROWS.stream().filter(wanted::contains).toList();
    }

    /**
     * @param specs the tasks (the same set for every executor)
     * @param work the calibrated busy loop
     * @param measuredNs measured time wanted per executor; rounded up to whole segments
     * @param segmentNs length of one executor's turn
     * @param progress where to print one line per round
     * @param rows the rows to run, labels of {@link #ROWS} (those of {@link #THREAD_PER_TASK_ROWS} are left
     *     out beyond {@link #THREAD_PER_TASK_LIMIT_PER_CORE})
     * @param workers threads of the pooled executors (rtaware's pool and the pooled STPE)
     * @param sleeper how rtaware's threaded executor sleeps its task threads (null: they park)
     * @param threadSetup run on rtaware's task threads and workers (e.g. the smallest timer slack); null for none.
     *     The other rows' threads keep the JVM's and the kernel's defaults, as a user's would
     */
    public CompareRun(List<BenchSpec> specs, BusyWork work, long measuredNs, long segmentNs, PrintStream progress,
                      List<String> rows, int workers, MonotonicSleeper sleeper, ThreadSetup threadSetup) {
        this.threadSetup = threadSetup;
        boolean threadPerTask = threadPerTaskFits(specs.size());
        this.rows = ROWS.stream().filter(rows::contains)
                .filter(r -> threadPerTask || !THREAD_PER_TASK_ROWS.contains(r)).toList();
        this.leftOut = ROWS.stream().filter(rows::contains).filter(r -> !this.rows.contains(r)).toList();
        this.workers = workers;
        this.sleeper = sleeper;
        this.specs = List.copyOf(specs);
        this.work = work;
        this.segmentNs = segmentNs;
        this.settleNs = settleNs(specs, segmentNs);
        this.rounds = (int) Math.max(1, (measuredNs + (segmentNs - settleNs) - 1) / (segmentNs - settleNs));
        this.progress = progress;
        this.threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
    }

    /**
     * The part of a segment not measured: 200 ms or three of the longest period, whichever is
     * longer, but at most half the segment.
     *
     * @param specs the tasks
     * @param segmentNs the segment length
     * @return the settle time in ns
     */
    static long settleNs(List<BenchSpec> specs, long segmentNs) {
        long longest = specs.stream().mapToLong(BenchSpec::periodNs).max().orElse(0);
        return Math.min(segmentNs / 2, Math.max(200_000_000L, 3 * longest));
    }

    /** @return the rows this comparison runs, in the table's order */
    public List<String> rows() {
        return rows;
    }

    /** @return the rows asked for that this task count leaves out (too many threads for the cores) */
    public List<String> leftOut() {
        return leftOut;
    }

    /** @return measured time per executor, ns */
    public long measuredNs() {
        return rounds * (segmentNs - settleNs);
    }

    /**
     * Runs warm-up and measured rounds.
     *
     * @return one row per executor run, in the order of {@link #ROWS}
     * @throws InterruptedException if interrupted
     */
    public List<RunResult> run() throws InterruptedException {
        if (threads.isThreadCpuTimeSupported()) {
            threads.setThreadCpuTimeEnabled(true);
        }
        ThreadAllocation.prepare();
        if (!leftOut.isEmpty()) {
            progress.printf("compare: %d tasks is more than %d per core: the executors with a thread per task "
                    + "(%s) are left out%n", specs.size(), THREAD_PER_TASK_LIMIT_PER_CORE, String.join(", ", leftOut));
        }
        Map<String, ExecutorTotals> totals = new LinkedHashMap<>();
        rows.forEach(name -> totals.put(name, new ExecutorTotals(name)));
        List<ReleaseStats> stats = new ArrayList<>();
        for (BenchSpec spec : specs) {
            stats.add(new ReleaseStats(spec.periodNs()));
        }
        for (int round = 0; round <= rounds; round++) {
            progress.printf("compare: round %d/%d%s%n", round, rounds, round == 0 ? " (warm-up, not counted)" : "");
            for (int i = 0; i < rows.size(); i++) {
                String name = rows.get((round + i) % rows.size());
                runSegment(segment(name), stats, round == 0 ? null : totals.get(name));
            }
        }
        return totals.values().stream().map(ExecutorTotals::result).toList();
    }

    /** @return a new executor of the row, for one segment */
    private SegmentExecutor segment(String row) {
        return switch (row) {
            case "rtaware" -> new RtawareSegment(work, row, ExecutorKind.threaded(), sleeper, threadSetup);
            case "rtaware-pooled" -> new RtawareSegment(work, row,
                    ExecutorKind.pooled(workers, ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST), sleeper, threadSetup);
            case "stpe" -> new StpeSegment(work, 0);
            case "stpe-pooled" -> new StpeSegment(work, workers);
            case "park-loop" -> new ParkLoopSegment(work);
            case "netty-wheel" -> new NettyWheelSegment(work);
            case "agrona-wheel" -> new AgronaWheelSegment(work);
            default -> throw new IllegalArgumentException("no comparison row '" + row + "'");
        };
    }

    private void runSegment(SegmentExecutor executor, List<ReleaseStats> stats, ExecutorTotals totals)
            throws InterruptedException {
        executor.prepare(specs, stats);
        // Collects the previous segments' garbage (a 1000-task monitor is 32 MB) now, while no
        // task thread runs: a collection started by it inside the next window would stop every
        // thread alive for its handshakes (ZGC's HandshakeAllThreads took up to 292 ms with 1000
        // task threads in issue 16's profile) and charge that to whichever executor runs then,
        // most often the one whose preparation allocated. A no-op under Epsilon.
        System.gc();
        stats.forEach(ReleaseStats::reset);
        executor.start(specs, stats);
        // The window opens a settle time after start() has returned, not after it was called:
        // starting 1000 threads took 75-250 ms here, and a window counted from the call let the
        // first releases of a slow start (all tasks at once, on cold caches) fall inside it
        // (issue 16: one such segment gave 620 misses and 1800 skipped releases, more than the
        // rest of a 30-round comparison).
        long fromNs = System.nanoTime() + settleNs;
        long untilNs = fromNs + segmentNs - settleNs;
        stats.forEach(s -> s.openWindow(fromNs, untilNs));
        parkUntil(fromNs);
        long[] ids = threadIds(executor, stats);
        long cpu0 = cpuNs(ids);
        ThreadAllocation allocation = ThreadAllocation.ofThreadIds(ids);
        parkUntil(untilNs);
        long cpu1 = cpuNs(ids);
        long allocatedBytes = allocation.allocatedSince();
        executor.stop();
        if (totals != null) {
            stats.forEach(totals::add);
            totals.endRound();
            totals.addCost(cpu1 - cpu0, allocatedBytes);
        }
    }

    /**
     * Task threads (known once each task has run) plus the executor's helper threads, each once
     * (a pool runs many tasks on one thread).
     */
    private static long[] threadIds(SegmentExecutor executor, List<ReleaseStats> stats) {
        long[] helpers = executor.helperThreadIds();
        long[] ids = new long[stats.size() + helpers.length];
        int n = 0;
        for (ReleaseStats s : stats) {
            if (s.threadId() != 0) {
                ids[n++] = s.threadId();
            }
        }
        for (long id : helpers) {
            ids[n++] = id;
        }
        return java.util.Arrays.stream(ids, 0, n).distinct().toArray();
    }

    private long cpuNs(long[] ids) {
        long sum = 0;
        for (long id : ids) {
            long t = threads.getThreadCpuTime(id);
            if (t > 0) {
                sum += t;
            }
        }
        return sum;
    }

    private static void parkUntil(long deadlineNs) throws InterruptedException {
        long remaining;
        while ((remaining = deadlineNs - System.nanoTime()) > 0) {
            LockSupport.parkNanos(remaining);
            if (Thread.interrupted()) {
                throw new InterruptedException();
            }
        }
    }

    /** @return the names of the collectors this JVM runs, e.g. {@code G1 Young Generation, G1 Old Generation} */
    public static String collectors() {
        return ManagementFactory.getGarbageCollectorMXBeans().stream()
                .map(GarbageCollectorMXBean::getName).collect(Collectors.joining(", "));
    }
}
