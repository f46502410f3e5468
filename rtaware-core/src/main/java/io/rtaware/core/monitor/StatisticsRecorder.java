package io.rtaware.core.monitor;

import io.rtaware.core.agent.ThreadNames;
import java.util.concurrent.locks.LockSupport;

/**
 * Records the pooled tasks' lateness and execution times into their histograms on a thread of
 * its own, after the workers' drains, so that a drain only notes the values.
 *
 * <p>Why: with 10 000 tasks released at one instant, recording into the tasks' histograms
 * (270 MB of them, a few scattered cache lines written per value) was the largest part of a
 * drain that the release itself does not need: without it the median task's p99 lateness was
 * 45 % lower on the VM of issue 36's session 8, and with this thread the median task's p50 (about
 * half a drain) fell by a fifth on a noisier one (docs/performance.md, "The histograms recorded
 * on a thread of their own"). A worker that has run a batch and finds nothing more due {@link #wake wakes} this
 * thread before it parks; the thread then makes one pass over the pool's tasks
 * ({@link #recordPass}) while the workers wait for the next releases.
 *
 * <p>The thread runs at normal priority: under {@code --realtime} it runs when the workers rest.
 * If it falls behind (a machine with no idle time), each task's cycle records its own values
 * once {@link StatisticsTable#RECORD_WHEN_WAITING} wait, and a value is never lost
 * ({@link StatisticsTable#released}). The claim a task's values are recorded under is the
 * table's; the reports read after the workers have stopped record what still waits.
 *
 * <p>Steady state allocates nothing (the histograms' one 64-bit copy aside, see
 * {@link CycleStatistics}); the thread is named {@value ThreadNames#STATISTICS} and counted
 * among the framework's threads on the release path by the allocation guard.
 */
final class StatisticsRecorder {

    private final StatisticsTable table;
    /** The tasks this recorder records, by their index in the table. */
    private final int[] tasks;
    private final FrameworkFaults faults;
    private final Thread thread;
    private volatile boolean stopped;

    /**
     * Takes over the recording of {@code tasks}' values (before their first cycle).
     *
     * @param tasks tasks of one monitor (at least one), whose statistics share its table
     * @param faults where a fault of the recording goes (the run goes on; the cycles record their
     *     values once too many wait)
     * @throws IllegalArgumentException if there are none, or they are not all of one monitor
     */
    StatisticsRecorder(TaskRuntime[] tasks, FrameworkFaults faults) {
        this(tableOf(tasks), indexesOf(tasks), faults);
    }

    /**
     * Takes over the recording of some tasks' values (before their first cycle).
     *
     * @param table the monitor's statistics
     * @param tasks the tasks' indexes in the table
     * @param faults where a fault of the recording goes
     */
    StatisticsRecorder(StatisticsTable table, int[] tasks, FrameworkFaults faults) {
        this.table = table;
        this.tasks = tasks.clone();
        for (int task : tasks) {
            table.recordedByRecorder(task);
        }
        this.faults = faults;
        this.thread = new Thread(this::run, ThreadNames.STATISTICS);
        thread.setDaemon(true);
    }

    private static StatisticsTable tableOf(TaskRuntime[] tasks) {
        if (tasks.length == 0) {
            throw new IllegalArgumentException(OffPathText.recorderForNoTask());
        }
        for (TaskRuntime task : tasks) {
            if (task.statisticsTable() != tasks[0].statisticsTable()) {
                throw new IllegalArgumentException(OffPathText.notOfOneMonitor(task.name(), tasks[0].name()));
            }
        }
        return tasks[0].statisticsTable();
    }

    private static int[] indexesOf(TaskRuntime[] tasks) {
        int[] indexes = new int[tasks.length];
        for (int i = 0; i < tasks.length; i++) {
            indexes[i] = tasks[i].index();
        }
        return indexes;
    }

    /** Starts the thread. */
    void start() {
        thread.start();
    }

    /**
     * Asks for a pass over the tasks (a worker that has run releases and is about to park):
     * wakes the thread, or has it make one more pass if it is making one now.
     */
    void wake() {
        LockSupport.unpark(thread);
    }

    /**
     * Records the waiting values of every task whose batch is due
     * ({@link StatisticsTable#recorderBatchDue}: {@value CycleStatistics#RECORD_BATCH} values, at
     * the task's phase) and whose values no other thread records now.
     *
     * <p>Why batches: recording the one new value of each of 10 000 tasks every pass touched two
     * cold histograms per value, about 230 ns each, and the thread took 45-54 % of a core at 10 ms
     * periods on issue 36's session 10 VM (2.27-2.68 s of CPU in 5 s, {@code /proc} schedstat;
     * 0.62-0.73 s in batches, docs/performance.md);
     * in batches, a task's histograms are touched once per {@value CycleStatistics#RECORD_BATCH}
     * values, as the cycles' own recording did, and the phases spread the tasks over the passes.
     * The histograms are read only once the cycles have stopped, after the rest is recorded
     * ({@link CycleStatistics#latenessUs}), so the values that wait meanwhile are never missing
     * from a report.
     *
     * @return how many tasks' values it recorded
     */
    int recordPass() {
        int recorded = 0;
        for (int task : tasks) {
            if (table.recorderBatchDue(task) && table.tryRecordWaiting(task)) {
                recorded++;
            }
        }
        return recorded;
    }

    /** Stops the thread and waits for it; what still waits is recorded by the reports. */
    void stopAndJoin() {
        stopped = true;
        LockSupport.unpark(thread);
        Watchdog.joinOrInterrupt(thread, Watchdog.JOIN_TIMEOUT_MS, faults);
    }

    private void run() {
        try {
            while (!stopped) {
                LockSupport.park(this);
                if (!stopped) {
                    recordPass();
                }
            }
        } catch (RuntimeException e) {
            faults.report(OffPathText.statisticsRecorder(), e);
        }
    }
}
