package io.rtaware.core.analysis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.report.Percentiles;
import io.rtaware.core.report.TaskReport;
import java.util.List;
import org.junit.jupiter.api.Test;

class SchedulabilityTest {

    /**
     * Textbook set (C, T) = (1, 4), (2, 6), (3, 12), deadlines = periods, RM order as given.
     * <pre>
     * R1 = 1
     * R2: 2 -> 2 + ceil(2/4)*1 = 3 -> 2 + ceil(3/4)*1 = 3            => R2 = 3
     * R3: 3 -> 3 + ceil(3/4)*1 + ceil(3/6)*2 = 6
     *       -> 3 + ceil(6/4)*1 + ceil(6/6)*2 = 7
     *       -> 3 + ceil(7/4)*1 + ceil(7/6)*2 = 9
     *       -> 3 + ceil(9/4)*1 + ceil(9/6)*2 = 10
     *       -> 3 + ceil(10/4)*1 + ceil(10/6)*2 = 10                  => R3 = 10 <= 12
     * U = 1/4 + 2/6 + 3/12 = 0.8333 > 3 (2^(1/3) - 1) = 0.7798: above the Liu-Layland bound,
     * yet schedulable by the exact test.
     * </pre>
     */
    @Test
    void responseTimesOfTheTextbookSet() {
        long[] r = Schedulability.responseTimes(new long[] {1, 2, 3}, new long[] {4, 6, 12}, new long[] {4, 6, 12});
        assertArrayEquals(new long[] {1, 3, 10}, r);
    }

    /**
     * (C, T) = (2, 4), (3, 6): U = 1.0. R2: 3 -> 3 + ceil(3/4)*2 = 5 -> 3 + ceil(5/4)*2 = 7 > 6.
     */
    @Test
    void responseTimePastTheDeadlineIsMinusOne() {
        long[] r = Schedulability.responseTimes(new long[] {2, 3}, new long[] {4, 6}, new long[] {4, 6});
        assertArrayEquals(new long[] {2, -1}, r);
    }

    /**
     * (C, T) = (1, 4), (2, 6), (4, 8) on one core: R3 = 4 + ceil(R/4) + 2 ceil(R/6): 4 -> 7 -> 10
     * -> 11 -> 11 > 8, a miss. On two cores, the bound of Bertogna and Cirinei, task 3 under tasks
     * 1 (R1 = 1) and 2 (R2 = 2, fewer tasks above it than cores), with
     * {@code W_i(L) = N C_i + min(C_i, L + R_i - C_i - N T_i)}, {@code N = floor((L + R_i - C_i) / T_i)}
     * and {@code R = C + floor(sum min(W_i(R), R - C + 1) / 2)}:
     * <pre>
     * R = 4: W1 = 1 + min(1, 0) = 1 -> 1; W2 = 0 + min(2, 4) = 2 -> min(2, 1) = 1; 4 + floor(2/2) = 5
     * R = 5: W1 = 1 + min(1, 1) = 2 -> 2; W2 = min(2, 5) = 2 -> 2;               5 + ... = 4 + 2 = 6
     * R = 6: W1 = 1 + min(1, 2) = 2 -> 2; W2 = 2 + min(2, 0) = 2 -> 2;           4 + 2 = 6  => R3 = 6 <= 8
     * </pre>
     */
    @Test
    void twoCoresClearATaskOneCoreCannot() {
        long[] c = {1, 2, 4};
        long[] t = {4, 6, 8};
        assertArrayEquals(new long[] {1, 3, -1}, Schedulability.responseTimes(c, t, t));
        assertArrayEquals(new long[] {1, 2, 6}, Schedulability.responseTimes(c, t, t, 2));
    }

    /** The bound needs its fixed point, not a step: with three tasks above on two cores the iteration climbs. */
    @Test
    void theGlobalBoundGrowsWithTheWorkAbove() {
        // Three tasks of (2, 5) above a task of (3, 10) on two cores.
        // R = 3: each W = 2 + min(2, 3 + 2 - 2 - 5) -> N = floor(3/5) = 0: W = min(2, 3) = 2 -> min(2, 1) = 1; 3 + floor(3/2) = 4
        // R = 4: N = floor(4/5) = 0, W = 2 -> min(2, 2) = 2 each; 3 + floor(6/2) = 6
        // R = 6: N = floor(6/5) = 1, W = 2 + min(2, 6 - 5) = 3 -> min(3, 4) = 3 each; 3 + floor(9/2) = 7
        // R = 7: N = 1, W = 2 + min(2, 2) = 4 -> min(4, 5) = 4 each; 3 + 6 = 9
        // R = 9: N = 1, W = 2 + min(2, 4) = 4 -> 4 each; 3 + 6 = 9 => 9 <= 10
        long[] r = Schedulability.responseTimes(new long[] {2, 2, 2, 3}, new long[] {5, 5, 5, 10},
                new long[] {5, 5, 5, 10}, 2);
        assertEquals(9, r[3]);
        assertEquals(2, r[0]);
        assertEquals(2, r[1], "fewer tasks above than cores: its own time");
    }

    /**
     * On two cores a task above that passes its own deadline (9 ns of work every 8 ns) takes one
     * core whole, not every core: the task below it still has the other, R = 5 + floor(1 / 2) = 5.
     * Two such tasks take both, and the task below has no bound.
     */
    @Test
    void aTaskAbovePastItsDeadlineTakesOneCoreWhole() {
        assertArrayEquals(new long[] {-1, 5}, Schedulability.responseTimes(new long[] {9, 5}, new long[] {8, 20},
                new long[] {8, 20}, 2));
        assertArrayEquals(new long[] {-1, -1, -1}, Schedulability.responseTimes(new long[] {9, 9, 5},
                new long[] {8, 8, 20}, new long[] {8, 8, 20}, 2));
    }

    /** A hand-edited report may hold a day of work every nanosecond: no overflow, no endless climb. */
    @Test
    void absurdFiguresSaturateInsteadOfOverflowing() {
        long day = 86_400_000_000_000L;
        long[] c = {day, day, 1};
        long[] t = {1, 1, 2};
        assertArrayEquals(new long[] {day, -1, -1}, Schedulability.responseTimes(c, t, new long[] {day, day, day}));
        assertArrayEquals(new long[] {day, day, -1}, Schedulability.responseTimes(c, t, new long[] {day, day, day}, 2),
                "each of the two day-long tasks has a core of its own; the third never gets one");
        var report = Reports.report(List.of(Reports.task("a", 1e-6, 8.64e16, 8.64e16, 1, 10, 0, 0),
                Reports.task("b", 1e-6, 1e-3, 1e-3, 1e-3, 10, 0, 0)), List.of(Reports.key("a.out", "a", 1e-9, "b")));
        Advice advice = PeriodAdvisor.advise(report, 2);
        assertEquals(2, advice.tasks().size());
    }

    @Test
    void liuLaylandBound() {
        assertEquals(1.0, Schedulability.liuLaylandBound(1), 1e-12);
        assertEquals(0.8284, Schedulability.liuLaylandBound(2), 1e-4);
        assertEquals(0.7798, Schedulability.liuLaylandBound(3), 1e-4);
    }

    @Test
    void analyzesAReportInRateMonotonicOrder() {
        // Registered slowest first; ms periods and exec times of the textbook set.
        var report = Reports.report(List.of(
                Reports.task("c", 12, 3000, 4000, 2000, 100, 0, 0),
                Reports.task("b", 6, 2000, 2000, 1000, 100, 0, 0),
                Reports.task("a", 4, 1000, 1000, 1000, 100, 0, 0),
                new TaskReport("sock", "continuous", null, null, 5, 5, 0, 0, 0, 0, 0, 0, Percentiles.EMPTY,
                        Percentiles.EMPTY)), List.of());
        SchedulabilityReport s = Schedulability.analyze(report, 2);

        assertEquals(List.of("a", "b", "c"), s.tasks().stream().map(TaskUtilization::task).toList());
        assertEquals(List.of("sock"), s.excludedTasks());
        TaskUtilization c = s.tasks().get(2);
        assertEquals(3, c.rmPriority());
        assertEquals(0.25, c.utilizationP99(), 1e-9);
        assertEquals(0.3333, c.utilizationMax(), 1e-9);
        assertEquals(10.0, c.responseP99Ms(), 1e-9);
        // With max exec 4 ms: 4 -> 4+1+2 = 7 -> 4+2+4 = 10 -> 4+3+4 = 11 -> 4+3+4 = 11 <= 12.
        assertEquals(11.0, c.responseMaxMs(), 1e-9);
        assertEquals(0.8333, s.utilizationP99(), 1e-9);
        assertEquals(0.9167, s.utilizationMax(), 1e-9);
        assertEquals(0.7798, s.liuLaylandBound(), 1e-9);
        assertFalse(s.liuLaylandHoldsP99());
        assertTrue(s.rtaSchedulableP99());
        assertTrue(s.rtaSchedulableMax());
        assertEquals(0.4167, s.utilizationPerCoreP99(), 1e-9);
        assertTrue(s.verdict().startsWith("schedulable on 2 cores under global rate-monotonic priorities"), s.verdict());
        assertTrue(s.verdict().contains("; schedulable on one core"), s.verdict());
        assertTrue(s.verdict().contains("although above the Liu-Layland bound"), s.verdict());
        assertTrue(s.rtaSchedulableP99OnCores());
        assertEquals(Schedulability.testOnCores(2), s.rtaTestOnCores());
    }

    @Test
    void overloadIsNamed() {
        var report = Reports.report(List.of(
                Reports.task("a", 10, 9000, 9500, 9000, 100, 0, 0),
                Reports.task("b", 10, 9000, 9500, 9000, 100, 0, 50)), List.of());
        SchedulabilityReport s = Schedulability.analyze(report, 1);
        assertFalse(s.rtaSchedulableP99());
        assertNull(s.tasks().get(1).responseP99Ms());
        assertEquals(9.0, s.tasks().get(0).responseP99Ms(), 1e-9);
        assertTrue(s.verdict().contains("'b' can miss its deadline"), s.verdict());
        assertTrue(s.verdict().contains("overloaded, needs at least 2 cores"), s.verdict());
        String text = AnalysisText.schedulability(s);
        assertTrue(text.contains("> deadline"), text);
    }
}
