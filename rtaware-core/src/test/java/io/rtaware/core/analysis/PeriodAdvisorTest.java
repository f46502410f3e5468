package io.rtaware.core.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class PeriodAdvisorTest {

    @Test
    void nyquistFlagsATaskSlowerThanTwiceItsInputRate() {
        // The paper's case: laser at 10 Hz, obstacle at 100 ms must run at <= 50 ms.
        var report = Reports.report(List.of(
                Reports.task("laser", 100, 100, 100, 100, 100, 0, 0),
                Reports.task("obstacle", 100, 500, 600, 400, 100, 0, 0),
                Reports.task("occupancy", 50, 500, 600, 400, 200, 100, 0)),
                List.of(Reports.key("laser", "laser", 10.0, "obstacle", "occupancy")));
        List<AdviceItem> advice = PeriodAdvisor.advise(report);
        assertEquals(1, advice.size(), advice.toString());
        AdviceItem item = advice.get(0);
        assertEquals("obstacle", item.task());
        assertEquals("nyquist", item.rule());
        assertEquals(100.0, item.periodMs());
        assertEquals(50.0, item.suggestedPeriodMs());
        assertEquals(10.0, item.evidence().get("input_rate_hz"));
        assertEquals(50.0, item.evidence().get("nyquist_bound_ms"));
    }

    @Test
    void nyquistToleratesRateNoise() {
        // 100.5 Hz gives a bound of 4.975 ms; a 5 ms consumer is within the 2% tolerance.
        var report = Reports.report(List.of(Reports.task("b", 5, 100, 100, 100, 100, 50, 0)),
                List.of(Reports.key("a.out", "a", 100.5, "b")));
        assertEquals(List.of(), PeriodAdvisor.advise(report));
    }

    @Test
    void mostlyStaleSaysHowMuchSlowerAndWhatItFrees() {
        // 'b' runs every 2 ms, its input changes at 50 Hz (bound 10 ms): 5x slower frees
        // 0.4 ms * (500 - 100) per second = 160 ms/s.
        var report = Reports.report(List.of(Reports.task("b", 2, 500, 600, 400, 1000, 900, 0)),
                List.of(Reports.key("a.out", "a", 50.0, "b")));
        List<AdviceItem> advice = PeriodAdvisor.advise(report);
        assertEquals(1, advice.size(), advice.toString());
        AdviceItem item = advice.get(0);
        assertEquals("mostly_stale", item.rule());
        assertEquals(10.0, item.suggestedPeriodMs());
        assertEquals(90.0, item.evidence().get("stale_pct"));
        assertEquals(5.0, item.evidence().get("slowdown_factor"));
        assertEquals(160.0, item.evidence().get("freed_cpu_ms_per_s"));
        assertTrue(item.message().contains("5.0x slower"), item.message());
    }

    @Test
    void execNearPeriodSuggestsALongerPeriod() {
        // p99 9 ms of a 10 ms period: 90%; 9 / 0.7 = 12.857 -> 12.9 ms.
        var report = Reports.report(List.of(Reports.task("a", 10, 9000, 9800, 8000, 100, 0, 3)), List.of());
        List<AdviceItem> advice = PeriodAdvisor.advise(report);
        assertEquals(1, advice.size());
        assertEquals("exec_near_period", advice.get(0).rule());
        assertEquals(12.9, advice.get(0).suggestedPeriodMs());
        assertTrue(advice.get(0).message().contains("lengthen the period to 12.9 ms"), advice.get(0).message());
    }

    @Test
    void execNearPeriodSaysLessWorkWhenNyquistForbidsALongerPeriod() {
        // Input at 50 Hz: bound 10 ms; 12.9 ms would break it, so: less work, p99 <= 7 ms.
        var report = Reports.report(List.of(Reports.task("b", 10, 9000, 9800, 8000, 100, 0, 3)),
                List.of(Reports.key("a.out", "a", 50.0, "b")));
        List<AdviceItem> advice = PeriodAdvisor.advise(report);
        assertEquals(1, advice.size(), advice.toString());
        assertEquals(10.0, advice.get(0).suggestedPeriodMs());
        assertEquals(7.0, advice.get(0).evidence().get("target_exec_ms"));
        assertTrue(advice.get(0).message().contains("do less work: p99 <= 7 ms"), advice.get(0).message());
        assertTrue(AnalysisText.advice(advice).contains("exec_near_period"));
    }

    /** Eight tasks of 10 ms released at once, lateness p99 3 ms (30 % of the period): one item for the group. */
    @Test
    void tasksReleasedTogetherAreToldToSpreadTheirOffsets() {
        List<io.rtaware.core.report.TaskReport> tasks = new java.util.ArrayList<>();
        for (int i = 0; i < 8; i++) {
            tasks.add(Reports.released("t" + i, 10, 20, 100 + 400 * i, 3000));
        }
        tasks.add(Reports.released("alone", 10, 5, 50, 90));
        List<AdviceItem> advice = PeriodAdvisor.advise(Reports.report(tasks, List.of()));
        assertEquals(1, advice.size(), advice.toString());
        AdviceItem item = advice.get(0);
        assertEquals("released_together", item.rule());
        assertEquals("t7", item.task(), "named after the task that starts latest");
        assertEquals(10.0, item.suggestedPeriodMs(), "the period stays: the offsets change");
        assertEquals(8, item.evidence().get("tasks_released_together"));
        assertEquals(0.0, item.evidence().get("offset_ms"), "20 ms is the same instant in a 10 ms period as 0 ms");
        assertEquals(3.0, item.evidence().get("lateness_p99_median_ms"));
        assertEquals("t0", item.evidence().get("first_task"));
        assertEquals(2.9, item.evidence().get("latest_lateness_p50_ms"));
        assertEquals(1.25, item.evidence().get("suggested_offset_step_ms"), "10 ms over 8 tasks");
        assertTrue(item.message().contains("'t7' and 7 other tasks of period 10 ms"), item.message());
    }

    @Test
    void releasedTogetherNeedsFourTasksOfOnePhaseAndALatenessThatShows() {
        List<io.rtaware.core.report.TaskReport> spread = new java.util.ArrayList<>();
        List<io.rtaware.core.report.TaskReport> early = new java.util.ArrayList<>();
        List<io.rtaware.core.report.TaskReport> three = new java.util.ArrayList<>();
        List<io.rtaware.core.report.TaskReport> unknown = new java.util.ArrayList<>();
        for (int i = 0; i < 8; i++) {
            spread.add(Reports.released("s" + i, 10, i * 1.25, 100, 3000));
            early.add(Reports.released("e" + i, 10, 0, 100, 999));
            unknown.add(Reports.task("u" + i, 10, 100, 100, 100, 100, 0, 0));
        }
        for (int i = 0; i < 3; i++) {
            three.add(Reports.released("h" + i, 10, 0, 100, 5000));
        }
        assertEquals(List.of(), PeriodAdvisor.advise(Reports.report(spread, List.of())), "each its own instant");
        assertEquals(List.of(), PeriodAdvisor.advise(Reports.report(early, List.of())), "p99 under 10 % of the period");
        assertEquals(List.of(), PeriodAdvisor.advise(Reports.report(three, List.of())), "fewer than four tasks");
        assertEquals(List.of(), PeriodAdvisor.advise(Reports.report(unknown, List.of())),
                "a report written before offsets were reported");
    }

    /** Issue 24: a period under 0.5 us rounded to 0 us and divided by zero, which cost the run its report. */
    @Test
    void periodsUnderAMicrosecondAreGroupedByTheNanosecond() {
        List<io.rtaware.core.report.TaskReport> tasks = new java.util.ArrayList<>();
        for (int i = 0; i < 4; i++) {
            tasks.add(Reports.released("n" + i, 0.0001, 0.0002, 0.1, 0.5)); // 100 ns, offset 200 ns: phase 0
        }
        tasks.add(Reports.released("other", 0.0001, 0.00005, 0.1, 0.5)); // phase 50 ns: its own instant
        List<AdviceItem> advice = PeriodAdvisor.advise(Reports.report(tasks, List.of()));
        List<AdviceItem> together = advice.stream().filter(a -> a.rule().equals("released_together")).toList();
        assertEquals(1, together.size(), advice.toString());
        assertEquals(4, together.get(0).evidence().get("tasks_released_together"));
        assertEquals(0.0, together.get(0).evidence().get("offset_ms"));
    }
}
