package io.rtaware.bench.compare;

import io.rtaware.core.testing.LiveThreads;
import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.monitor.ExecutorKind;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.MonitorListener;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.monitor.ThreadSetup;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.MonotonicSleeper;
import io.rtaware.core.time.SystemClock;
import java.util.List;
import java.util.stream.LongStream;
import java.util.stream.Stream;

/**
 * rtaware on one of its executors (threaded: {@code rtaware}; pooled: {@code rtaware-pooled}): a
 * {@link Monitor} with one {@link BurnTask} per task, whose cycle is the body every other row
 * runs (the calibrated busy loop, nothing else), so the rows differ only in how releases get
 * onto threads and what is accounted around them. Lateness is the monitor's own measurement
 * (the release and start it reports in {@link MonitorListener#onCycle}), skipped releases are the
 * ones it reports. The monitor's watchdog and pool workers count as framework cost.
 */
final class RtawareSegment implements SegmentExecutor {

    private final BusyWork work;
    private final String name;
    private final ExecutorKind kind;
    private final MonotonicSleeper sleeper;
    private final ThreadSetup threadSetup;
    private Monitor monitor;

    /**
     * @param work the calibrated busy loop
     * @param name the row's name
     * @param kind the executor
     * @param sleeper how the threaded executor's task threads sleep (null: they park)
     * @param threadSetup run on the task threads and workers, or null
     */
    RtawareSegment(BusyWork work, String name, ExecutorKind kind, MonotonicSleeper sleeper, ThreadSetup threadSetup) {
        this.threadSetup = threadSetup;
        this.work = work;
        this.name = name;
        this.kind = kind;
        this.sleeper = sleeper;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public void prepare(List<BenchSpec> specs, List<ReleaseStats> stats) {
        Monitor.Builder builder = Monitor.builder(new SystemClock()).executor(kind).sleeper(sleeper)
                .threadSetup(threadSetup);
        for (BenchSpec s : specs) {
            builder.task(s.name(), s.schedule(), new BurnTask(s.workNs(), work));
        }
        builder.listener(new StatsListener(stats.toArray(new ReleaseStats[0])));
        monitor = builder.build();
    }

    @Override
    public void start(List<BenchSpec> specs, List<ReleaseStats> stats) {
        monitor.start();
    }

    /**
     * Finds the watchdog, the pool's workers and its statistics recorder by name among the live
     * threads with {@link Thread#enumerate}, not
     * {@code Thread.getAllStackTraces()}: that one stops every thread at a safepoint and walks
     * all their stacks (1000 task threads: 28 MB and a stall inside the measured window, seen
     * in issue 16's profile).
     */
    @Override
    public long[] helperThreadIds() {
        return Stream.of(ThreadNames.WATCHDOG, ThreadNames.POOL_WORKER_PREFIX, ThreadNames.STATISTICS)
                .map(LiveThreads::idsNamed).flatMapToLong(LongStream::of).toArray();
    }

    @Override
    public void stop() {
        monitor.stop();
    }

    /** Forwards the monitor's per-cycle measurements; allocation-free. */
    private static final class StatsListener implements MonitorListener {
        private final ReleaseStats[] stats;

        StatsListener(ReleaseStats[] stats) {
            this.stats = stats;
        }

        @Override
        public void onCycle(TaskInfo task, long releaseNs, long startNs, long endNs) {
            stats[task.index()].onRun(releaseNs, startNs, endNs);
        }

        @Override
        public void onSkippedReleases(TaskInfo task, long skipped, long nowNs) {
            stats[task.index()].onSkipped(skipped, nowNs);
        }
    }

    /**
     * The compared task body: the busy loop and nothing else, as the park loop and
     * {@code ScheduledThreadPoolExecutor} rows run it. It declares no data: the cost of a commit
     * to the data store is measured on its own ({@code StoreBench}), and {@code rtaware bench}
     * without {@code --compare} runs tasks that publish. (Until issue 16's last session this row
     * ran those publishing tasks, a store commit per release that no other row made.)
     */
    private static final class BurnTask implements Task {
        private final long workNs;
        private final BusyWork work;

        BurnTask(long workNs, BusyWork work) {
            this.workNs = workNs;
            this.work = work;
        }

        @Override
        public void initialize(TaskSetup setup) {
            // Declares no data.
        }

        @Override
        public void execute(long nowNs) {
            work.burn(workNs);
        }
    }
}
