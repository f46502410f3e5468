package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ConditionsMeterTest {

    @Test
    void aRunBesideOtherProcessesIsBusyWithTheirShareNamed(@TempDir Path root) throws IOException {
        HostReaderTest.lay("busy-start", root);
        AtomicLong now = new AtomicLong();
        FakeJvm jvm = new FakeJvm();
        ConditionsMeter meter = new ConditionsMeter(new HostReader(new HostFiles(root), now::get), jvm,
                new BuildInfo("0.1.0", "abc123"));
        ConditionsMeter.Span span = meter.start(10, "none");
        HostReaderTest.lay("busy-end", root);
        now.set(10_000_000_000L);
        jvm.gcCount = 3;
        jvm.gcTotalMs = 0.6;
        jvm.gcMaxPauseMs = 0.3;
        jvm.stopsMs = new double[] {0.3, 0.05, 0.3};
        Conditions c = span.finish(10);

        MeasuredConditions m = c.measured();
        assertEquals(10.0, m.durationS(), 1e-12);
        // 2000 ticks over the span on 2 CPUs. The other processes' own counters grew by 1600: stress-ng
        // 1400, bash 100 for the cc1 it reaped, make (new) 100; 1600 * 2 / 2000. (The machine's busy
        // ticks minus this process's happen to agree here: 1800 - 200.)
        assertEquals(1.6, m.otherCpus(), 1e-12, "the other processes' CPU by their own counters, in CPUs");
        assertEquals(1.0, m.stealPct(), 1e-12, "20 of 2000 ticks stolen");
        assertEquals(14.2, m.loadStart(), 1e-12);
        assertEquals(15.0, m.loadEnd(), 1e-12);
        assertEquals(42, m.involuntarySwitches(), "52 at the end minus 10 at the start, over both threads");
        assertEquals(100.0 * (12_288 + 524_288) / 633_868, m.hugePagesPct(), 1e-9,
                "the end's smaps_rollup: 12 MiB of anonymous and 512 MiB of shared huge pages, of 619 MiB resident");
        assertEquals(3, m.gcCount());
        assertEquals(0.3, m.gcMaxPauseMs(), 1e-12);
        assertNull(m.timeToSafepointMaxMs(), "the fake JVM does not measure it");
        assertTrue(jvm.closed, "finishing stops the pause counting");

        assertEquals("busy", c.machine());
        assertEquals("machine: busy (other processes used 1.6 of 2 CPUs (more than 0.10); load 14.2 at start)",
                c.summaryLine());
        // The 10 ms period at time scale 10 lasts 1 ms on the machine: stops are judged against 0.1 ms.
        assertEquals(0.1, m.longStopLimitMs(), 1e-12);
        assertEquals(2, m.longStops());
        StaticConditions s = c.setup();
        assertEquals("AMD EPYC 7B13", s.cpuModel());
        assertEquals(1.5, s.usableCpus(), 1e-12);
        assertEquals("Test Vendor", s.jvmVendor());
        assertEquals(List.of("-XX:+UseZGC", "-Xmx512m"), s.jvmOptions());
        assertEquals(512, s.heapMaxMb());
        assertEquals("abc123", s.gitCommit());
        assertEquals(10.0, s.timeScale());
        assertEquals("kvm-clock", s.clockSource());
        assertEquals(c, span.finish(10), "a second finish gives the same conditions");
    }

    @Test
    void theVerdictSoFarFollowsTheRunAndIsTheFinalOneOnceFinished(@TempDir Path root) throws IOException {
        AtomicLong now = new AtomicLong();
        FakeJvm jvm = new FakeJvm();
        ConditionsMeter.Span span = busyTenSeconds(root, now, jvm);
        Conditions later = span.sofar(100);
        assertEquals("busy", later.machine(), "the other processes' 1.6 CPUs since the start");
        assertEquals(10.0, later.measured().durationS(), 1e-12);
        assertTrue(!jvm.closed, "the measurement goes on");
        jvm.gcCount = 2;
        assertEquals(2, span.sofar(100).measured().gcCount(), "pauses since the last look count too");
        Conditions end = span.finish(100);
        now.set(20_000_000_000L);
        assertEquals(end, span.sofar(100), "after the finish, the final conditions");
    }

    @Test
    void stopsAreJudgedAgainstThePeriodInWallTime(@TempDir Path root) throws IOException {
        for (double scale : new double[] {1, 10}) {
            HostReaderTest.lay("busy-start", root);
            AtomicLong now = new AtomicLong();
            FakeJvm jvm = new FakeJvm();
            ConditionsMeter meter = new ConditionsMeter(new HostReader(new HostFiles(root), now::get), jvm,
                    new BuildInfo("0.1.0", null));
            ConditionsMeter.Span span = meter.start(scale, "none");
            HostReaderTest.lay("busy-end", root);
            now.set(10_000_000_000L);
            jvm.gcCount = 20;
            jvm.gcMaxPauseMs = 0.5;
            jvm.stopsMs = new double[20];
            java.util.Arrays.fill(jvm.stopsMs, 0.5);
            // 10 s of 100 ms periods: 100 periods at time scale 1 (limit 10 ms, no stop is long), 1000 of 10 ms
            // at time scale 10 (limit 1 ms): no stop is long either; 20 stops of 0.5 ms only count against 1 ms
            // periods, i.e. a 10 ms world period at time scale 10.
            MeasuredConditions slow = span.finish(100).measured();
            assertEquals(0, slow.longStops());
            assertEquals(10.0 / scale, slow.longStopLimitMs(), 1e-12);
        }
        HostReaderTest.lay("busy-start", root);
        FakeJvm jvm = new FakeJvm();
        AtomicLong now = new AtomicLong();
        ConditionsMeter.Span span = new ConditionsMeter(new HostReader(new HostFiles(root), now::get), jvm,
                new BuildInfo("0.1.0", null)).start(10, "none");
        HostReaderTest.lay("busy-end", root);
        now.set(10_000_000_000L);
        jvm.stopsMs = new double[20];
        java.util.Arrays.fill(jvm.stopsMs, 0.5);
        Conditions c = span.finish(10);
        assertEquals(20, c.measured().longStops(), "0.5 ms stops against the 0.1 ms limit of a 1 ms wall period");
        assertTrue(c.machineReasons().stream().anyMatch(r -> r.startsWith("20 JVM stops longer than 0.10 ms")),
                c.machineReasons().toString());
    }

    @Test
    void theMcapMetadataCarriesVerdictSetupAndMeasuredFigures(@TempDir Path root) throws IOException {
        HostReaderTest.lay("busy-start", root);
        AtomicLong now = new AtomicLong();
        ConditionsMeter meter = new ConditionsMeter(new HostReader(new HostFiles(root), now::get), new FakeJvm(),
                new BuildInfo("0.1.0", null));
        ConditionsMeter.Span span = meter.start(1, "none");
        HostReaderTest.lay("busy-end", root);
        now.set(10_000_000_000L);
        Map<String, String> md = ConditionsMeter.metadata(span.finish(Double.NaN));
        assertEquals("busy", md.get("machine"));
        assertTrue(md.get("measured").contains("\"other_cpus\":1.6"), md.get("measured"));
        assertTrue(md.get("setup").contains("\"cpu_model\":\"AMD EPYC 7B13\""), md.get("setup"));
        assertTrue(md.get("setup").contains("\"git_commit\":null"), md.get("setup"));
    }

    @Test
    void otherProcessesAreCountedByTheirOwnCountersAndAReusedIdAsANewProcess() {
        // 1 grew by 100; 2's counters went down, so a new process took its id: all 30 of it;
        // 3 ended (its parent's reaped time would count it); 4 is new: 7
        assertEquals(100 + 30 + 7, MeasuredConditions.othersTicks(Map.of(1L, 50L, 2L, 500L, 3L, 9L),
                Map.of(1L, 150L, 2L, 30L, 4L, 7L)));
        assertEquals(-1, MeasuredConditions.othersTicks(null, Map.of()), "no table at the start");
        assertEquals(-1, MeasuredConditions.othersTicks(Map.of(), null), "no table at the end");
    }

    /**
     * The third red team's two ways round the process table: children reaped where nobody counts
     * them (a parent that ignores SIGCHLD) were invisible, and a late reaper's whole-life
     * children's time gave "other processes used 9.6 of 2 CPUs".
     */
    @Test
    void theProcessTableIsHeldNearTheMachinesBusyTimeAndNeverAboveItsCpus() {
        // 2 CPUs, 10 s: 2000 ticks. This process used 200 ticks (0.2 CPU): noise 0.05 CPU.
        HostSample start = new HostSample(0, 1, 2, 1_000, 100, 0, 50, 0, Map.of(7L, 10L), Double.NaN);
        // The machine was busy 1200 ticks, 1000 of them not this process's (1.0 CPU), the table saw 20.
        HostSample unseen = new HostSample(10_000_000_000L, 1, 2, 3_000, 1_300, 0, 250, 0, Map.of(7L, 30L), Double.NaN);
        assertEquals(1.0 - 0.05, MeasuredConditions.between(start, unseen, null, Double.NaN).otherCpus(), 1e-12,
                "auto-reaped children: the machine's busy time less its noise");
        // A late reaper's cutime: 9 600 ticks in the table, the machine only 300 busy ticks beyond this process.
        HostSample late = new HostSample(10_000_000_000L, 1, 2, 3_000, 600, 0, 250, 0, Map.of(7L, 9_610L), Double.NaN);
        assertEquals(0.3 + 0.05, MeasuredConditions.between(start, late, null, Double.NaN).otherCpus(), 1e-12,
                "a whole life reaped at once: the machine's busy time plus its noise");
        // Within the noise the exact counters stand.
        HostSample agree = new HostSample(10_000_000_000L, 1, 2, 3_000, 600, 0, 250, 0, Map.of(7L, 290L), Double.NaN);
        assertEquals(0.28, MeasuredConditions.between(start, agree, null, Double.NaN).otherCpus(), 1e-12);
        // Impossible ticks (a machine counter that ran backwards into nonsense) never give more than the CPUs.
        HostSample wild = new HostSample(10_000_000_000L, 1, 2, 3_000, 99_000, 0, 250, 0, null, Double.NaN);
        assertEquals(2.0, MeasuredConditions.between(start, wild, null, Double.NaN).otherCpus(), 1e-12);
    }

    @Test
    void withoutAProcessTableTheMachinesBusyTimeMinusThisProcessIsUsed() {
        HostSample start = new HostSample(0, 1, 2, 1_000, 100, 0, 50, 0, null, Double.NaN);
        HostSample end = new HostSample(10_000_000_000L, 1, 2, 3_000, 700, 0, 250, 0, null, Double.NaN);
        // 600 busy ticks minus 200 of this process's, over 2000 ticks on 2 CPUs
        assertEquals(0.4, MeasuredConditions.between(start, end, null, Double.NaN).otherCpus(), 1e-12);
        HostSample withTable = new HostSample(10_000_000_000L, 1, 2, 3_000, 700, 0, 250, 0, Map.of(7L, 20L), Double.NaN);
        assertEquals(0.4, MeasuredConditions.between(start, withTable, null, Double.NaN).otherCpus(), 1e-12,
                "a table at one end only is no table");
    }

    @Test
    void theWindowEndsWhenEndIsCalledNotWhenTheConditionsAreMade(@TempDir Path root) throws IOException {
        AtomicLong now = new AtomicLong();
        FakeJvm jvm = new FakeJvm();
        ConditionsMeter.Span span = busyTenSeconds(root, now, jvm);
        span.end(); // the tasks stopped
        assertTrue(jvm.closed, "the pauses after the tasks stopped are not counted");
        now.set(25_000_000_000L); // the report of many tasks took 15 s to build
        span.end();
        assertEquals(10.0, span.sofar(100).measured().durationS(), 1e-12, "so far: the window ended");
        assertEquals(10.0, span.finish(100).measured().durationS(), 1e-12, "the window is the run's");
    }

    /** A span at time scale 1 over the "busy" fixture's two samples, its clock moved to 10 s. */
    private static ConditionsMeter.Span busyTenSeconds(Path root, AtomicLong now, FakeJvm jvm) throws IOException {
        HostReaderTest.lay("busy-start", root);
        ConditionsMeter.Span span = new ConditionsMeter(new HostReader(new HostFiles(root), now::get), jvm,
                new BuildInfo("0.1.0", null)).start(1, "none");
        HostReaderTest.lay("busy-end", root);
        now.set(10_000_000_000L);
        return span;
    }
}
