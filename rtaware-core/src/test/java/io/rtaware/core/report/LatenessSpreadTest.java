package io.rtaware.core.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class LatenessSpreadTest {

    private static TaskReport periodic(String name, long releases, double p99Us) {
        return new TaskReport(name, "periodic", 10.0, 10.0, releases, releases, 0, 0, 0, 0, 0, 0,
                Percentiles.EMPTY, new Percentiles(p99Us / 4, p99Us / 2, p99Us, p99Us * 2, p99Us / 3));
    }

    private static Report report(double missesPct, TaskReport... tasks) {
        return new Report(Report.SCHEMA, 1, 10, missesPct, List.of(tasks), List.of());
    }

    @Test
    void theMedianOfAnOddCountIsTheMiddleTasksAndTheWorstIsNamed() {
        LatenessSpread spread = LatenessSpread.of(report(0.05, periodic("a", 100, 300), periodic("b", 100, 5_870),
                periodic("c", 100, 3_310))).orElseThrow();
        assertEquals(new LatenessSpread(3, 3_310, 5_870, "b", 0.05), spread);
        assertEquals("p99 lateness over 3 periodic tasks: the median task's 3.31 ms, the worst 5.87 ms (b);"
                + " misses 0.05 % of all releases", spread.line());
    }

    @Test
    void theMedianOfAnEvenCountIsTheMeanOfTheTwoMiddleOnesAndTheFirstOfEqualWorstIsNamed() {
        LatenessSpread spread = LatenessSpread.of(report(1.5, periodic("a", 10, 100), periodic("b", 10, 900),
                periodic("c", 10, 300), periodic("d", 10, 900))).orElseThrow();
        assertEquals(600, spread.medianP99Us(), 1e-9, "(300 + 900) / 2");
        assertEquals("b", spread.worstTask());
    }

    @Test
    void tasksWithoutAPeriodOrNeverReleasedAreLeftOut() {
        TaskReport once = new TaskReport("once", "once", null, null, 1, 1, 0, 0, 0, 0, 0, 0,
                Percentiles.EMPTY, new Percentiles(1, 1, 99_000, 99_000, 1));
        LatenessSpread spread = LatenessSpread.of(report(0, once, periodic("idle", 0, 50_000), periodic("a", 5, 700)))
                .orElseThrow();
        assertEquals(new LatenessSpread(1, 700, 700, "a", 0), spread);
        assertTrue(spread.line().startsWith("p99 lateness over 1 periodic task:"), spread.line());
        assertTrue(LatenessSpread.of(report(0, once)).isEmpty(), "no periodic task: no spread");
    }
}
