package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.report.Percentiles;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import org.HdrHistogram.Histogram;
import org.junit.jupiter.api.Test;

/** The pool's statistics recorder: who records a task's values, and that none is lost or counted twice. */
class StatisticsRecorderTest {

    private static final FrameworkFaults NO_FAULTS = new FrameworkFaults((source, error) -> {
        throw new AssertionError(source, error);
    });

    /** Notes one cycle of task i: its release with this lateness, its end with this execution time. */
    private static void cycle(StatisticsTable table, int i, long latenessNs, long execNs) {
        if (table.released(i, latenessNs)) {
            table.tryRecordWaiting(i);
        }
        if (table.cycleEnded(i, execNs)) {
            table.tryRecordWaiting(i);
        }
    }

    @Test
    void aRecordedTaskWaitsForItsRecorderAndTheOthersRecordAtTheirPhase() {
        StatisticsTable table = new StatisticsTable(3);
        List<CycleStatistics> tasks = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            tasks.add(new CycleStatistics(table, i, 0));
        }
        StatisticsRecorder recorder = new StatisticsRecorder(table, new int[] {0, 2}, NO_FAULTS);
        for (int n = 0; n < CycleStatistics.RECORD_BATCH; n++) {
            for (int i = 0; i < 3; i++) {
                cycle(table, i, 1_000 + n, 500 + n);
            }
        }
        assertEquals(CycleStatistics.RECORD_BATCH, tasks.get(0).latenessWaiting(),
                "the recorder's task does not record at its phase");
        assertEquals(0, tasks.get(1).latenessWaiting(), "a task of the cycle's own recording records at its phase");
        assertEquals(CycleStatistics.RECORD_BATCH, tasks.get(2).latenessWaiting());
        assertTrue(table.recorderBatchDue(0));

        assertEquals(2, recorder.recordPass(), "the pass records both of its tasks, each with a batch waiting");
        assertEquals(0, tasks.get(0).latenessWaiting());
        assertEquals(0, tasks.get(2).latenessWaiting());
        assertEquals(0, tasks.get(2).execWaiting(), "execution times too");
        assertEquals(0, recorder.recordPass(), "nothing waits: nothing to record");
        assertEquals(CycleStatistics.RECORD_BATCH, table.latenessHistograms[0].getTotalCount());
        assertEquals(CycleStatistics.RECORD_BATCH, table.execHistograms[2].getTotalCount());
    }

    @Test
    void aPassRecordsATaskOnlyOnceABatchOfItsValuesWaits() {
        StatisticsTable table = new StatisticsTable(1);
        CycleStatistics task = new CycleStatistics(table, 0, 0);
        StatisticsRecorder recorder = new StatisticsRecorder(table, new int[] {0}, NO_FAULTS);
        for (int n = 1; n < CycleStatistics.RECORD_BATCH; n++) {
            cycle(table, 0, 1_000 + n, 500);
            assertEquals(0, recorder.recordPass(), "after " + n + " cycles the values wait for a batch");
            assertEquals(n, task.latenessWaiting());
        }
        cycle(table, 0, 2_000, 500);
        assertEquals(1, recorder.recordPass(), "a batch waits: recorded at once");
        assertEquals(0, task.latenessWaiting());
        assertEquals(0, task.execWaiting());
        assertEquals(CycleStatistics.RECORD_BATCH, table.latenessHistograms[0].getTotalCount());

        cycle(table, 0, 3_000, 500);
        assertFalse(table.recorderBatchDue(0));
        assertEquals(0, recorder.recordPass());
        task.latenessUs();
        assertEquals(CycleStatistics.RECORD_BATCH + 1, table.latenessHistograms[0].getTotalCount(),
                "the report records what still waits");
        assertEquals(0, task.latenessWaiting());
    }

    @Test
    void aRecorderRecordsEachTaskAtItsPhaseSoThatTasksReleasedTogetherAreSpreadOverThePasses() {
        StatisticsTable table = new StatisticsTable(2);
        new CycleStatistics(table, 0, 0);
        CycleStatistics late = new CycleStatistics(table, 1, 5);
        StatisticsRecorder recorder = new StatisticsRecorder(table, new int[] {0, 1}, NO_FAULTS);
        List<Integer> recordedAtCycle = new ArrayList<>();
        for (int n = 1; n <= 3 * CycleStatistics.RECORD_BATCH; n++) {
            cycle(table, 0, 1_000, 500);
            cycle(table, 1, 1_000, 500);
            long before = late.latenessWaiting();
            int recorded = recorder.recordPass();
            if (before > 0 && late.latenessWaiting() == 0) {
                recordedAtCycle.add(n);
            }
            assertTrue(recorded <= 1, "the two tasks' phases differ: never both in one pass (cycle " + n + ")");
        }
        assertEquals(List.of(5, 21, 37), recordedAtCycle, "a shorter first batch at phase 5, then every 16 cycles");
    }

    @Test
    void aCycleWhoseRecorderFallsBehindRecordsItsOwnValues() {
        StatisticsTable table = new StatisticsTable(1);
        CycleStatistics task = new CycleStatistics(table, 0, 0);
        new StatisticsRecorder(table, new int[] {0}, NO_FAULTS);
        long most = 0;
        for (int n = 0; n < 5 * CycleStatistics.WAITING_CAPACITY; n++) {
            cycle(table, 0, 1_000 + n, 500);
            most = Math.max(most, task.latenessWaiting());
        }
        assertEquals(StatisticsTable.RECORD_WHEN_WAITING - 1, most,
                "with no pass at all, the cycle records once " + StatisticsTable.RECORD_WHEN_WAITING + " wait");
    }

    /**
     * A cycle's thread notes values while another thread makes passes: whatever the interleaving,
     * the report holds every value once (the claim gives a task's histograms one writer at a time).
     */
    @Test
    void valuesNotedWhileARecorderPassesAreEachRecordedOnce() throws InterruptedException {
        int tasks = 4;
        int cycles = 20_000;
        StatisticsTable table = new StatisticsTable(tasks);
        List<CycleStatistics> statistics = new ArrayList<>();
        for (int i = 0; i < tasks; i++) {
            statistics.add(new CycleStatistics(table, i, i));
        }
        StatisticsRecorder recorder = new StatisticsRecorder(table, new int[] {0, 1, 2, 3}, NO_FAULTS);
        AtomicBoolean noting = new AtomicBoolean(true);
        Thread passes = new Thread(() -> {
            while (noting.get()) {
                recorder.recordPass();
            }
        });
        passes.start();
        for (int n = 0; n < cycles; n++) {
            for (int i = 0; i < tasks; i++) {
                cycle(table, i, valueNs(i, n), 2 * valueNs(i, n));
            }
        }
        noting.set(false);
        passes.join();
        for (int i = 0; i < tasks; i++) {
            Histogram lateness = new Histogram(1, 3_600_000_000_000L, 2);
            Histogram exec = new Histogram(1, 3_600_000_000_000L, 2);
            long maxNs = 0;
            double sumNs = 0;
            for (int n = 0; n < cycles; n++) {
                lateness.recordValue(valueNs(i, n));
                exec.recordValue(2 * valueNs(i, n));
                maxNs = Math.max(maxNs, valueNs(i, n));
                sumNs += valueNs(i, n);
            }
            assertEquals(Percentiles.ofNanos(lateness, maxNs, sumNs), statistics.get(i).latenessUs(), "task " + i);
            assertEquals(Percentiles.ofNanos(exec, 2 * maxNs, 2 * sumNs), statistics.get(i).execUs(), "task " + i);
            assertEquals(cycles, table.latenessHistograms[i].getTotalCount(), "task " + i + ": none counted twice");
        }
    }

    private static long valueNs(int task, int cycle) {
        return 2_000 + 97L * ((cycle * 31L + task * 7L) % 1000);
    }

    @Test
    void aRecorderForNoTaskIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new StatisticsRecorder(new TaskRuntime[0], NO_FAULTS));
    }
}
