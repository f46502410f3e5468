package io.rtaware.bench.compare;

import io.rtaware.core.testing.LiveThreads;
import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * What a Java developer would otherwise write: {@link ScheduledThreadPoolExecutor#scheduleAtFixedRate}.
 * Thread per task ({@code stpe}): each task gets a pool of its own with one thread, so every task
 * has a thread to itself, as under rtaware's threaded executor. Pooled ({@code stpe-pooled}): one
 * pool with as many threads as rtaware's pooled executor has workers, for every task. Run i of a
 * task is intended at {@code t0 + offset + i * period} (fixed rate: the pool runs late runs back to back,
 * it never skips, so a backlog shows as lateness growing past a period and as misses), and its
 * lateness is measured against that.
 */
final class StpeSegment implements SegmentExecutor {

    private static final long STOP_TIMEOUT_S = 10;
    private static final long START_AHEAD_NS = 10_000_000;

    private final BusyWork work;
    /** Threads of the one shared pool; 0: a one-thread pool per task. */
    private final int sharedThreads;
    private final List<ScheduledThreadPoolExecutor> pools = new ArrayList<>();

    /**
     * @param work the calibrated busy loop
     * @param sharedThreads threads of one pool shared by every task; 0 for a pool per task
     */
    StpeSegment(BusyWork work, int sharedThreads) {
        this.work = work;
        this.sharedThreads = sharedThreads;
    }

    @Override
    public String name() {
        return sharedThreads == 0 ? "stpe" : "stpe-pooled";
    }

    @Override
    public void prepare(List<BenchSpec> specs, List<ReleaseStats> stats) {
        if (sharedThreads > 0) {
            ScheduledThreadPoolExecutor shared = pool(sharedThreads, "stpe-pool");
            specs.forEach(spec -> pools.add(shared));
            return;
        }
        for (BenchSpec spec : specs) {
            pools.add(pool(1, "stpe-" + spec.name()));
        }
    }

    private static ScheduledThreadPoolExecutor pool(int threads, String name) {
        int[] created = new int[1];
        return new ScheduledThreadPoolExecutor(threads, r -> {
            Thread thread = new Thread(r, threads == 1 ? name : name + "-" + created[0]++);
            thread.setDaemon(true);
            return thread;
        });
    }

    @Override
    public void start(List<BenchSpec> specs, List<ReleaseStats> stats) {
        // The pools exist; t0 lies just ahead, so every task's first run is intended at t0 plus its offset.
        long t0 = System.nanoTime() + START_AHEAD_NS;
        for (int i = 0; i < specs.size(); i++) {
            BenchSpec spec = specs.get(i);
            long firstNs = t0 + spec.offsetNs();
            FixedRateRun run = new FixedRateRun(firstNs, spec.periodNs(), spec.workNs(), work, stats.get(i));
            pools.get(i).scheduleAtFixedRate(run, Math.max(0, firstNs - System.nanoTime()), spec.periodNs(),
                    TimeUnit.NANOSECONDS);
        }
    }

    @Override
    public long[] helperThreadIds() {
        return sharedThreads == 0 ? new long[0] : LiveThreads.idsNamed("stpe-pool-");
    }

    @Override
    public void stop() throws InterruptedException {
        pools.forEach(ScheduledThreadPoolExecutor::shutdownNow);
        for (ScheduledThreadPoolExecutor pool : new java.util.LinkedHashSet<>(pools)) {
            pool.awaitTermination(STOP_TIMEOUT_S, TimeUnit.SECONDS);
        }
    }

    /** One task's runnable: the work plus the bookkeeping against {@code t0 + i * period}. */
    private static final class FixedRateRun implements Runnable {
        private final long t0Ns;
        private final long periodNs;
        private final long workNs;
        private final BusyWork work;
        private final ReleaseStats stats;
        private long run;

        FixedRateRun(long t0Ns, long periodNs, long workNs, BusyWork work, ReleaseStats stats) {
            this.t0Ns = t0Ns;
            this.periodNs = periodNs;
            this.workNs = workNs;
            this.work = work;
            this.stats = stats;
        }

        @Override
        public void run() {
            long startNs = System.nanoTime();
            work.burn(workNs);
            stats.onRun(t0Ns + run * periodNs, startNs, System.nanoTime());
            run++;
        }
    }
}
