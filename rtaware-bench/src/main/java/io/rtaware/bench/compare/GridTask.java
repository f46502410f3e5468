package io.rtaware.bench.compare;

import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import java.util.List;
import java.util.function.LongSupplier;

/**
 * One task of the rows that are not rtaware's and keep their own release grid (the park loop, the
 * timer wheels): releases intended at {@code first + k * period}, each run being the calibrated
 * busy loop recorded against its release in the task's {@link ReleaseStats}. After a run that
 * ended past later releases the task moves to the first grid point at or after the run's end and
 * counts the ones passed over as skipped: the same rule as rtaware's executors (without it a
 * stall's backlog would run late back to back, and the row would measure the backlog, not the
 * wake-up). A user of a timer re-arms a periodic timer the same way, at the next grid point
 * rather than {@code now + period}, which would drift.
 *
 * <p>Allocation-free. Not thread-safe: one thread at a time runs a task.
 */
final class GridTask {

    private final long firstNs;
    private final long periodNs;
    private final long workNs;
    private final BusyWork work;
    private final ReleaseStats stats;
    private final LongSupplier nanoTime;
    private long release;

    /**
     * @param firstNs the first release
     * @param periodNs the period
     * @param workNs the work per run
     * @param work the calibrated busy loop
     * @param stats the task's bookkeeping
     * @param nanoTime the clock ({@code System::nanoTime}; a manual one in tests)
     */
    GridTask(long firstNs, long periodNs, long workNs, BusyWork work, ReleaseStats stats, LongSupplier nanoTime) {
        this.firstNs = firstNs;
        this.periodNs = periodNs;
        this.workNs = workNs;
        this.work = work;
        this.stats = stats;
        this.nanoTime = nanoTime;
    }

    /**
     * @param specs the tasks
     * @param stats their bookkeeping, in the same order
     * @param t0Ns the instant every task's offset counts from
     * @param work the calibrated busy loop
     * @return one task each, on {@link System#nanoTime()}, first released at {@code t0 + offset}
     */
    static GridTask[] of(List<BenchSpec> specs, List<ReleaseStats> stats, long t0Ns, BusyWork work) {
        GridTask[] tasks = new GridTask[specs.size()];
        for (int i = 0; i < tasks.length; i++) {
            BenchSpec spec = specs.get(i);
            tasks[i] = new GridTask(t0Ns + spec.offsetNs(), spec.periodNs(), spec.workNs(), work, stats.get(i),
                    System::nanoTime);
        }
        return tasks;
    }

    /** @return the release due next, ns */
    long releaseNs() {
        return firstNs + release * periodNs;
    }

    /**
     * Runs the release due now: its start is now, its lateness is measured against
     * {@link #releaseNs()}; then moves to the next grid point at or after the run's end.
     *
     * @return the next release, ns
     */
    long run() {
        long releaseNs = releaseNs();
        long startNs = nanoTime.getAsLong();
        work.burn(workNs);
        long endNs = nanoTime.getAsLong();
        stats.onRun(releaseNs, startNs, endNs);
        long next = Math.max(release + 1, Math.floorDiv(endNs - firstNs + periodNs - 1, periodNs));
        if (next > release + 1) {
            stats.onSkipped(next - release - 1, endNs);
        }
        release = next;
        return releaseNs();
    }
}
