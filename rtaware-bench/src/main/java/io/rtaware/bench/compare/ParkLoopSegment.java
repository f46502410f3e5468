package io.rtaware.bench.compare;

import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;

/**
 * The floor for a Java thread: one thread per task parking until the absolute release
 * {@code t0 + offset + k * period} with {@link LockSupport#parkNanos}, then doing the work. After a run
 * that ended past later releases it skips to the first grid point at or after its end, the same
 * rule as rtaware (without it, every release of a stall's backlog would run late back to back
 * and the floor's lateness would measure the backlog, not the wake-up). Nothing else: no
 * monitoring, no data, no watchdog, so the difference to rtaware is the framework's cost.
 */
final class ParkLoopSegment implements SegmentExecutor {

    private static final long JOIN_TIMEOUT_MS = 10_000;

    private final BusyWork work;
    private final List<Thread> threads = new ArrayList<>();
    private volatile boolean running;

    ParkLoopSegment(BusyWork work) {
        this.work = work;
    }

    @Override
    public String name() {
        return "park-loop";
    }

    @Override
    public void start(List<BenchSpec> specs, List<ReleaseStats> stats) {
        running = true;
        long t0 = System.nanoTime();
        GridTask[] tasks = GridTask.of(specs, stats, t0, work);
        for (int i = 0; i < tasks.length; i++) {
            GridTask task = tasks[i];
            Thread thread = new Thread(() -> loop(task), "park-" + specs.get(i).name());
            thread.setDaemon(true);
            threads.add(thread);
        }
        threads.forEach(Thread::start);
    }

    private void loop(GridTask task) {
        while (running) {
            long releaseNs = task.releaseNs();
            long remainingNs;
            while ((remainingNs = releaseNs - System.nanoTime()) > 0 && running) {
                LockSupport.parkNanos(remainingNs);
            }
            if (!running) {
                return;
            }
            task.run();
        }
    }

    @Override
    public long[] helperThreadIds() {
        return new long[0];
    }

    @Override
    public void stop() throws InterruptedException {
        running = false;
        threads.forEach(LockSupport::unpark);
        for (Thread thread : threads) {
            thread.join(JOIN_TIMEOUT_MS);
        }
    }
}
