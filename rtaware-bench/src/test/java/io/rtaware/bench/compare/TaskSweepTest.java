package io.rtaware.bench.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.conditions.ConditionsMeter;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.image.BufferedImage;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The sweep's table and plot, from fixed rows. */
class TaskSweepTest {

    private static RunResult row(String executor, long releases, long misses, double p99, double p999) {
        return new RunResult(executor, new RunResult.Lateness(10, p99, p999, 2 * p999), releases, misses, 0, 1, 0);
    }

    @Test
    void tablePrintsMissPercentAndTailPerExecutorAndTaskCount() {
        TaskSweep sweep = new TaskSweep();
        sweep.add(10, row("rtaware", 1000, 0, 120, 300));
        sweep.add(10, row("park-loop", 1000, 0, 110, 250));
        sweep.add(1000, row("rtaware", 100_000, 2500, 9000, 40_000));
        sweep.add(1000, row("park-loop", 100_000, 150, 8000, 10_000));

        List<String> lines = sweep.table().lines().toList();
        assertEquals(5, lines.size(), "a header and one line per executor and count");
        assertTrue(lines.get(3).matches("rtaware\\s+1000\\s+100000\\s+2\\.50 \\|\\s+9000\\.0us\\s+40000\\.0us"), lines.get(3));
        assertEquals(2.5, sweep.points().get(2).missPct());

        BufferedImage image = sweep.plot("period 10 ms, work 0", List.of());
        assertEquals(900, image.getWidth());
        assertEquals(850, image.getHeight(), "two plots, one above the other, and a margin");
    }

    @Test
    void rowsLeftOutAtACountAreSaidInTheTableAndInTheFigureWithTheConditions() {
        TaskSweep sweep = new TaskSweep();
        sweep.add(10, row("rtaware", 1000, 0, 120, 300));
        sweep.add(10, row("netty-wheel", 1000, 0, 1100, 1900));
        sweep.leftOut(10_000, List.of("rtaware"));
        sweep.add(10_000, row("netty-wheel", 1_000_000, 0, 1500, 2500));

        String notRun = "not run at 10000 tasks: rtaware (a thread per task, more than 1000 per core)";
        assertEquals(List.of(notRun), sweep.leftOutLines());
        assertTrue(sweep.table().lines().anyMatch(notRun::equals), sweep.table());

        Conditions conditions = ConditionsMeter.ofThisProcess().start(1.0, "none").finish(10);
        List<String> caption = TaskSweep.caption(conditions, Instant.parse("2026-11-27T23:40:12Z"));
        assertEquals(4, caption.size(), "machine, JVM, load verdict, date");
        assertTrue(caption.get(0).startsWith("host: "), caption.get(0));
        assertTrue(caption.get(1).startsWith("JVM: "), caption.get(1));
        assertEquals(conditions.summaryLine(), caption.get(2));
        assertEquals("run 2026-11-27 23:40 UTC", caption.get(3));
        assertEquals(850 + 5 * 18, sweep.plot("period 10 ms", List.of("a", "b", "c", "d")).getHeight(),
                "a line each under the plots, the row left out first");
    }

    @Test
    void aCaptionLineWiderThanTheFigureIsBrokenAtSpaces() {
        FontMetrics metrics = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics()
                .getFontMetrics(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        String verdict = "machine: busy (other processes used 1.6 of 2 CPUs (more than 0.10); 40 JVM stops longer "
                + "than 1.00 ms (0.1 of the shortest period, 10.0 ms of wall time) in 5000 such periods)";
        List<String> lines = TaskSweep.wrap(List.of("run 2026-11-27 23:34 UTC", verdict), metrics, 400);
        assertEquals("run 2026-11-27 23:34 UTC", lines.get(0));
        assertTrue(lines.size() > 2, lines.toString());
        assertTrue(lines.stream().allMatch(l -> metrics.stringWidth(l) <= 400), lines.toString());
        assertEquals(verdict, String.join(" ", lines.subList(1, lines.size())).replaceAll(" +", " "));
    }
}
