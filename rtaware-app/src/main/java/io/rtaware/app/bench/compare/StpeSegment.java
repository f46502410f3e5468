package io.rtaware.app.bench.compare;

import io.rtaware.app.bench.BenchSpec;
import io.rtaware.app.bench.BusyWork;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * What a Java developer would otherwise write: {@link ScheduledThreadPoolExecutor#scheduleAtFixedRate}.
 * Each task gets a pool of its own with one thread, so every task has a thread to itself, as
 * under rtaware. Run i of a task is intended at {@code t0 + i * period} (fixed rate: the pool
 * runs late runs back to back, it never skips), and its lateness is measured against that.
 */
final class StpeSegment implements SegmentExecutor {

    private static final long STOP_TIMEOUT_S = 10;
    private static final long START_AHEAD_NS = 10_000_000;

    private final BusyWork work;
    private final List<ScheduledThreadPoolExecutor> pools = new ArrayList<>();

    StpeSegment(BusyWork work) {
        this.work = work;
    }

    @Override
    public String name() {
        return "stpe";
    }

    @Override
    public void start(List<BenchSpec> specs, List<ReleaseStats> stats) {
        for (BenchSpec spec : specs) {
            pools.add(new ScheduledThreadPoolExecutor(1, r -> {
                Thread thread = new Thread(r, "stpe-" + spec.name());
                thread.setDaemon(true);
                return thread;
            }));
        }
        // The pools exist; t0 lies just ahead, so every task's first run is intended at the same t0.
        long t0 = System.nanoTime() + START_AHEAD_NS;
        for (int i = 0; i < specs.size(); i++) {
            BenchSpec spec = specs.get(i);
            FixedRateRun run = new FixedRateRun(t0, spec.periodNs(), spec.workNs(), work, stats.get(i));
            pools.get(i).scheduleAtFixedRate(run, Math.max(0, t0 - System.nanoTime()), spec.periodNs(),
                    TimeUnit.NANOSECONDS);
        }
    }

    @Override
    public long[] helperThreadIds() {
        return new long[0];
    }

    @Override
    public void stop() throws InterruptedException {
        pools.forEach(ScheduledThreadPoolExecutor::shutdownNow);
        for (ScheduledThreadPoolExecutor pool : pools) {
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
