package io.rtaware.ros2.export;

import io.rtaware.core.monitor.CycleOutcome;
import io.rtaware.core.monitor.MonitorListener;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.ros2msg.statistics.TimingStatistics;
import java.io.IOException;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The exporter's ear on the monitor: a listener that copies every commit, cycle record and run
 * of skipped releases, on the task thread that reports it, into that task's ring of
 * {@value #SLOTS_PER_TASK} records allocated once; the exporter's thread drains the rings into
 * its {@link TimingStatistics}. A task reports on one thread at a time (its own, or the pooled
 * worker running its cycle), so each ring has one producer and one consumer and keeps the task's
 * order. A full ring drops the record and counts it ({@link #dropped()}); the listener's methods
 * never block and allocate nothing.
 */
final class TimingFeed implements MonitorListener {

    /** Records each task's ring holds. */
    static final int SLOTS_PER_TASK = 4096;
    private static final long COMMIT = 1;
    private static final long CYCLE = 2;
    private static final long SKIPPED = 3;
    /** Longs of a record before a cycle's input generations: kind and outcome, then three values. */
    private static final int HEADER = 4;
    private static final CycleOutcome[] OUTCOMES = CycleOutcome.values();

    /** One task's records: kind (and a cycle's outcome), three values, a cycle's generations. */
    private static final class TaskRing {
        final long[] records;
        final int width;
        final long[] generations;
        /** Records written: advanced by the producer after a record is whole. */
        final AtomicLong written = new AtomicLong();
        /** Records read: advanced by the consumer after it has read one. */
        final AtomicLong read = new AtomicLong();

        TaskRing(int inputs) {
            width = HEADER + inputs;
            records = new long[SLOTS_PER_TASK * width];
            generations = new long[inputs];
        }

        /** Producer: the start of a free record, or -1 if the ring is full. */
        int claim() {
            long w = written.get();
            return w - read.get() >= SLOTS_PER_TASK ? -1 : (int) (w % SLOTS_PER_TASK) * width;
        }

        /** Producer: the claimed record is whole. */
        void publish() {
            written.lazySet(written.get() + 1);
        }
    }

    private final TaskRing[] rings;
    private final AtomicLong dropped = new AtomicLong();

    /** @param inputsPerTask how many inputs each task has, by task index */
    TimingFeed(int[] inputsPerTask) {
        rings = new TaskRing[inputsPerTask.length];
        for (int t = 0; t < inputsPerTask.length; t++) {
            rings[t] = new TaskRing(inputsPerTask[t]);
        }
    }

    /**
     * @param tasks the monitor's tasks, in index order
     * @return a feed sized for their inputs
     */
    static TimingFeed of(List<TaskInfo> tasks) {
        int[] inputs = new int[tasks.size()];
        for (TaskInfo t : tasks) {
            inputs[t.index()] = t.inputKeys().size();
        }
        return new TimingFeed(inputs);
    }

    @Override
    public void onCommit(TaskInfo producer, int keyIndex, long generation, long nowNs) {
        put(producer.index(), COMMIT, keyIndex, generation, nowNs, null);
    }

    @Override
    public void onCycleRecord(TaskInfo task, CycleOutcome outcome, long releaseNs, long startNs, long endNs,
                              long[] inputGenerations) {
        put(task.index(), CYCLE | (long) outcome.ordinal() << 8, releaseNs, startNs, endNs, inputGenerations);
    }

    @Override
    public void onSkippedReleases(TaskInfo task, long skipped, long nowNs) {
        put(task.index(), SKIPPED, skipped, nowNs, 0, null);
    }

    private void put(int task, long kind, long a, long b, long c, long[] generations) {
        TaskRing ring = rings[task];
        int at = ring.claim();
        if (at < 0) {
            dropped.incrementAndGet();
            return;
        }
        long[] r = ring.records;
        r[at] = kind;
        r[at + 1] = a;
        r[at + 2] = b;
        r[at + 3] = c;
        for (int i = HEADER; i < ring.width; i++) {
            r[at + i] = generations == null ? 0 : generations[i - HEADER];
        }
        ring.publish();
    }

    /**
     * Hands every record written so far to the statistics, task by task (the exporter's thread
     * only).
     *
     * @param statistics where they go
     * @return records handed over
     * @throws IOException if publishing a window that a record forced out fails
     */
    int drainInto(TimingStatistics statistics) throws IOException {
        int n = 0;
        for (int task = 0; task < rings.length; task++) {
            TaskRing ring = rings[task];
            long end = ring.written.get();
            for (long next = ring.read.get(); next < end; next++) {
                int at = (int) (next % SLOTS_PER_TASK) * ring.width;
                long[] r = ring.records;
                long kind = r[at] & 0xff;
                if (kind == COMMIT) {
                    statistics.commit((int) r[at + 1], r[at + 2], r[at + 3]);
                } else if (kind == SKIPPED) {
                    statistics.skipped(task, r[at + 1], r[at + 2]);
                } else {
                    System.arraycopy(r, at + HEADER, ring.generations, 0, ring.generations.length);
                    statistics.cycle(task, OUTCOMES[(int) (r[at] >>> 8)], r[at + 1], r[at + 2], r[at + 3],
                            ring.generations);
                }
                ring.read.lazySet(next + 1);
                n++;
            }
        }
        return n;
    }

    /** @return records dropped because a task's ring was full */
    long dropped() {
        return dropped.get();
    }
}
