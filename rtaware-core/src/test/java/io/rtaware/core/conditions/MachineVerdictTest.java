package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class MachineVerdictTest {

    private static MeasuredConditions measured(double otherCpus, double stealPct, double gcMaxMs, Double ttspMs) {
        return new MeasuredConditions(10, 0.5, 0.6, 2, otherCpus, stealPct, gcMaxMs > 0 ? 1 : 0, gcMaxMs, gcMaxMs,
                ttspMs == null ? -1 : 1, ttspMs, null, 5);
    }

    @Test
    void belowEveryThresholdIsQuietAndSaysTheFigures() {
        MachineVerdict v = MachineVerdict.of(measured(0.05, 0.0, 0.2, 0.1), 10);
        assertEquals(MachineVerdict.QUIET, v.verdict());
        assertEquals("machine: quiet (other processes used 0.05 of 2 CPUs; steal 0.0 %; longest GC pause 0.20 ms; "
                + "load 0.5 at start)", v.text());
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
    void aPauseLongerThanATenthOfTheShortestPeriodDisturbs() {
        assertEquals(MachineVerdict.QUIET, MachineVerdict.of(measured(0, 0, 1.0, null), 10).verdict(),
                "1 ms is a tenth of 10 ms, not more");
        MachineVerdict gc = MachineVerdict.of(measured(0, 0, 1.5, null), 10);
        assertEquals(MachineVerdict.DISTURBED, gc.verdict());
        assertEquals(List.of("a GC pause of 1.50 ms (longer than 1.00 ms, 0.1 of the 10.0 ms period)"), gc.reasons());
        MachineVerdict ttsp = MachineVerdict.of(measured(0, 0, 0, 2.0), 10);
        assertEquals(MachineVerdict.DISTURBED, ttsp.verdict());
        assertTrue(ttsp.reasons().get(0).startsWith("a time to safepoint of 2.00 ms"), ttsp.reasons().toString());
        assertEquals(MachineVerdict.QUIET, MachineVerdict.of(measured(0, 0, 50, 50.0), Double.NaN).verdict(),
                "without a period pauses are not judged");
    }

    @Test
    void busyWinsOverDisturbedAndListsBoth() {
        MachineVerdict v = MachineVerdict.of(measured(1.2, 0, 5, null), 10);
        assertEquals(MachineVerdict.BUSY, v.verdict());
        assertEquals(2, v.reasons().size(), v.reasons().toString());
    }

    @Test
    void withoutCpuCountersTheVerdictIsUnknown() {
        assertEquals(MachineVerdict.UNKNOWN, MachineVerdict.of(measured(Double.NaN, Double.NaN, 0, null), 10).verdict());
    }
}
