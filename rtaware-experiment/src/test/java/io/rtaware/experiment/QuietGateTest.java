package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.conditions.HostSample;
import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.conditions.MeasuredConditions;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** The wait for a quiet machine, on a manual clock: checks are scripted, sleeping advances the clock. */
class QuietGateTest {

    private static final MachineCheck.Reading QUIET = new MachineCheck.Reading(new MachineVerdict(MachineVerdict.QUIET,
            List.of("other processes used 0.02 of 2 CPUs"), "load 0.3 at start"), 0.02, 0.5, 0.3);
    private static final MachineCheck.Reading BUSY = new MachineCheck.Reading(new MachineVerdict(MachineVerdict.BUSY,
            List.of("other processes used 1.00 of 2 CPUs (more than 0.10)"), "load 2.0 at start"), 1.0, 0.0, 2.0);

    private final AtomicLong nowNs = new AtomicLong();
    private final ByteArrayOutputStream shown = new ByteArrayOutputStream();
    private final ProgressBar bar = new ProgressBar(new PrintStream(shown, true, StandardCharsets.UTF_8), false,
            nowNs::get, 1);

    private QuietGate gate(Deque<MachineCheck.Reading> checks, double maxWaitS, boolean allowBusy) {
        return new QuietGate(checks::removeFirst, s -> nowNs.addAndGet((long) (s * 1e9)), nowNs::get, maxWaitS, allowBusy);
    }

    @Test
    void aBusyMachineIsWaitedForUntilItIsQuietAndTheReasonIsShown() throws Exception {
        Deque<MachineCheck.Reading> checks = new ArrayDeque<>(List.of(BUSY, BUSY, QUIET));
        QuietGate.Passage p = gate(checks, 300, false).await(bar, () -> false);
        assertEquals("quiet", p.beforeRun());
        assertEquals(List.of(0.02, 0.5, 0.3), List.of(p.otherCpus(), p.stealPct(), p.load1()), "the last check's readings");
        assertEquals(2 * QuietGate.RETRY_S, p.waitedS(), 1e-9, "two waits of " + QuietGate.RETRY_S + " s");
        String out = shown.toString(StandardCharsets.UTF_8);
        assertTrue(out.contains("[waiting] waiting for a quiet machine (0 of at most 300 s): machine: busy (other processes"
                + " used 1.00 of 2 CPUs (more than 0.10); load 2.0 at start)"), out);
        assertTrue(out.contains("(5 of at most 300 s)"), out);
    }

    @Test
    void theWaitIsBoundedAndTheRunIsThenLabelledBusy() throws Exception {
        Deque<MachineCheck.Reading> checks = new ArrayDeque<>(List.of(BUSY, BUSY, BUSY, BUSY));
        QuietGate.Passage p = gate(checks, 12, false).await(bar, () -> false);
        assertEquals("busy", p.beforeRun());
        assertEquals(1.0, p.otherCpus());
        assertEquals(12, p.waitedS(), 1e-9, "5 + 5 + the 2 s left");
        assertEquals(0, checks.size(), "checked at 0, 5, 10 and 12 s");
        assertTrue(shown.toString(StandardCharsets.UTF_8).contains("waited 12 s for a quiet machine, the most allowed"));
    }

    @Test
    void anInterruptedExperimentStopsWaitingAtTheNextCheck() throws Exception {
        Deque<MachineCheck.Reading> checks = new ArrayDeque<>(List.of(BUSY, BUSY, BUSY));
        int[] asked = {0};
        QuietGate.Passage p = gate(checks, 300, false).await(bar, () -> asked[0]++ >= 2);
        assertEquals("interrupted", p.beforeRun());
        assertEquals(2 * QuietGate.RETRY_S, p.waitedS(), 1e-9);
    }

    @Test
    void allowBusyRunsAtOnceAndLabels() throws Exception {
        QuietGate.Passage p = gate(new ArrayDeque<>(List.of(BUSY)), 300, true).await(bar, () -> false);
        assertEquals("busy", p.beforeRun());
        assertEquals(0, p.waitedS());
    }

    @Test
    void theCheckJudgesAndRecordsTheOtherProcessesOwnCountersNotTheTickSampledBusyTime() {
        // 2 CPUs over 1 s at 100 ticks/s: 200 ticks. The machine's tick-sampled busy time is 12
        // ticks (0.12 CPUs, busy by the old figure); the other processes' own counters grew by 8
        // ticks (0.08 CPUs), within the 0.05-CPU tick noise of it: that is the figure judged.
        HostSample start = new HostSample(0, 0.4, 2, 1000, 100, 0, 0, 0, Map.of(7L, 50L, 9L, 10L), Double.NaN);
        HostSample end = new HostSample(1_000_000_000L, 0.5, 2, 1200, 112, 0, 0, 0, Map.of(7L, 55L, 9L, 13L), Double.NaN);
        MachineCheck.Reading r = MachineCheck.Reading.of(MeasuredConditions.between(start, end, null, Double.NaN));
        assertEquals(0.08, r.otherCpus(), 1e-12);
        assertEquals(0.0, r.stealPct());
        assertEquals(0.5, r.load1());
        assertTrue(r.verdict().quiet(), r.verdict().text());
    }
}
