package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class MachineVerdictTest {

    /** Ten seconds; stops counted against 1 ms (a tenth of the 10 ms period the tests judge by). */
    private static MeasuredConditions measured(double otherCpus, double stealPct, double gcMaxMs, Double ttspMs,
                                               long longStops) {
        return new MeasuredConditions(10, 0.5, 0.6, 2, otherCpus, stealPct, gcMaxMs > 0 ? 1 : 0, gcMaxMs, gcMaxMs,
                ttspMs == null ? -1 : 1, ttspMs, null, 1.0, longStops, 5, 0.5, null, Double.NaN);
    }

    private static MeasuredConditions stalled(double longestStallMs) {
        return new MeasuredConditions(10, 0.5, 0.6, 2, 0.01, 0, 0, 0, 0, -1, null, null, 1.0, 0, 5, longestStallMs, null, Double.NaN);
    }

    private static MeasuredConditions measured(double otherCpus, double stealPct, double gcMaxMs, Double ttspMs) {
        return measured(otherCpus, stealPct, gcMaxMs, ttspMs, 0);
    }

    @Test
    void belowEveryThresholdIsQuietAndSaysTheFigures() {
        MachineVerdict v = MachineVerdict.of(measured(0.05, 0.0, 0.2, 0.1), 10);
        assertEquals(MachineVerdict.QUIET, v.verdict());
        assertEquals("machine: quiet (other processes used 0.05 of 2 CPUs; steal 0.0 %; 0 JVM stops longer than 1.00 ms"
                + " (0.1 of the shortest period, 10.0 ms of wall time) in 1000 such periods (longest GC pause 0.20 ms,"
                + " longest time to safepoint 0.10 ms); load 0.5 at start)", v.text());
    }

    /**
     * The third red team stopped the run with SIGSTOP for 5 s: 13.67 % misses, a 50 s late
     * maximum, judged quiet (no CPU counter moves while the process is stopped).
     */
    @Test
    void aStopOfTheWholeProcessLongerThan100msAndTheShortestPeriodDisturbsTheRun() {
        MachineVerdict stopped = MachineVerdict.of(stalled(5_012.5), 10);
        assertEquals(MachineVerdict.DISTURBED, stopped.verdict());
        assertEquals(List.of("the whole process was stopped for 5012.5 ms (its own watcher thread woke that late; more "
                + "than 100 ms and the shortest period, 10.0 ms)"), stopped.reasons());
        assertEquals(MachineVerdict.QUIET, MachineVerdict.of(stalled(99), 10).verdict(), "under 100 ms");
        assertEquals(MachineVerdict.QUIET, MachineVerdict.of(stalled(150), 200).verdict(), "within the shortest period");
        assertEquals(MachineVerdict.DISTURBED, MachineVerdict.of(stalled(150), Double.NaN).verdict(), "no period");
        assertEquals(MachineVerdict.QUIET, MachineVerdict.of(stalled(Double.NaN), 10).verdict(), "not measured");
    }

    @Test
    void otherProcessesAboveATenthOfOneCpuMakeItBusy() {
        assertEquals(MachineVerdict.QUIET, MachineVerdict.of(measured(0.10, 0, 0, null), 10).verdict(),
                "0.10 is at the threshold, not above it");
        MachineVerdict v = MachineVerdict.of(measured(0.11, 0, 0, null), 10);
        assertEquals(MachineVerdict.BUSY, v.verdict());
        assertEquals(List.of("other processes used 0.11 of 2 CPUs (more than 0.10)"), v.reasons());
    }

    @Test
    void stealAboveTwoPercentMakesItBusy() {
        MachineVerdict v = MachineVerdict.of(measured(0.0, 2.5, 0, null), 10);
        assertEquals(MachineVerdict.BUSY, v.verdict());
        assertEquals(List.of("steal 2.5 % (above 2 %)"), v.reasons());
    }

    @Test
    void moreThanOneLongStopPerThousandPeriodsDisturbs() {
        // 10 s of 10 ms periods: 1000 periods, so one stop longer than 1 ms is allowed, two are not.
        assertEquals(MachineVerdict.QUIET, MachineVerdict.of(measured(0, 0, 1.5, 2.0, 1), 10).verdict(),
                "one long stop in 1000 periods can delay one release of each task, no more");
        MachineVerdict v = MachineVerdict.of(measured(0, 0, 1.5, 2.0, 2), 10);
        assertEquals(MachineVerdict.DISTURBED, v.verdict());
        assertEquals(List.of("2 JVM stops longer than 1.00 ms (0.1 of the shortest period, 10.0 ms of wall time) in 1000"
                + " such periods, more than 1 per 1000 (longest GC pause 1.50 ms, longest time to safepoint 2.00 ms)"),
                v.reasons());
        assertEquals(MachineVerdict.DISTURBED, MachineVerdict.of(measured(0, 0, 1.5, null, 21), 100).verdict(),
                "100 periods of 100 ms in 10 s: the count is per period, not per run");
        assertEquals(MachineVerdict.QUIET, MachineVerdict.of(measured(0, 0, 50, 50.0, 40), Double.NaN).verdict(),
                "without a period pauses are not judged");
    }

    @Test
    void busyWinsOverDisturbedAndListsBoth() {
        MachineVerdict v = MachineVerdict.of(measured(1.2, 0, 5, null, 3), 10);
        assertEquals(MachineVerdict.BUSY, v.verdict());
        assertEquals(2, v.reasons().size(), v.reasons().toString());
    }

    @Test
    void withoutCpuCountersTheVerdictIsUnknown() {
        assertEquals(MachineVerdict.UNKNOWN, MachineVerdict.of(measured(Double.NaN, Double.NaN, 0, null), 10).verdict());
    }
}
