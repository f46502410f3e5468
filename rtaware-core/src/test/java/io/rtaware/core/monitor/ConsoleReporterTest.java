package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.testing.FixedTaskInfo;
import io.rtaware.core.time.ManualClock;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The live console: few enough lines per task to read, and every count lands in some line. */
class ConsoleReporterTest {

    private static final long MS = 1_000_000L;

    private final ByteArrayOutputStream buffer = new ByteArrayOutputStream();
    private final ManualClock wall = new ManualClock(10_000 * MS);
    private ConsoleReporter reporter;
    private TaskInfo planner;
    private TaskInfo mapper;

    @BeforeEach
    void setUp() {
        planner = task("planner", 0);
        mapper = task("mapper", 1);
        reporter = new ConsoleReporter(new PrintStream(buffer, true, StandardCharsets.UTF_8),
                List.of(planner, mapper), true, wall, false);
    }

    private static TaskInfo task(String name, int index) {
        return new FixedTaskInfo(name, index, Schedule.periodic(100 * MS), List.of());
    }

    private List<String> lines() {
        return buffer.toString(StandardCharsets.UTF_8).lines().toList();
    }

    private void misses(TaskInfo task, int n) {
        for (int i = 0; i < n; i++) {
            reporter.onDeadlineMiss(task, 0, 100 * MS, 150 * MS, true);
        }
    }

    private static long countOf(List<String> lines, String task, String what) {
        return sumOf(lines, Pattern.compile("\\] " + task + ":.*? (\\d+) " + what));
    }

    /** @return the sum over the lines of the number the pattern's first group finds, once a line */
    private static long sumOf(List<String> lines, Pattern p) {
        long sum = 0;
        for (String line : lines) {
            Matcher m = p.matcher(line);
            if (m.find()) {
                sum += Long.parseLong(m.group(1));
            }
        }
        return sum;
    }

    @Test
    void atMostOneLinePerSecondPerTaskWithFoldedCounts() {
        misses(planner, 3);
        reporter.poll();
        assertEquals(1, lines().size(), "first events are printed at the next poll: " + lines());
        assertTrue(lines().get(0).contains("planner: 3 deadline misses"), lines().get(0));

        misses(planner, 4);
        wall.advance(500 * MS);
        reporter.poll();
        assertEquals(1, lines().size(), "no second line for the same task within a second");

        wall.advance(600 * MS);
        reporter.poll();
        assertEquals(2, lines().size(), "a second later the folded events get their line");
        assertTrue(lines().get(1).contains("planner: 4 deadline misses"), lines().get(1));
    }

    /** Issue 34: 62-121 miss lines on stderr in a 30 s run, one per task per second. */
    @Test
    void aTaskMissingThroughoutARunGetsFewerLinesTheLongerItLasts() {
        for (int poll = 0; poll < 300; poll++) { // 30 s, a poll every 100 ms, misses all along
            misses(planner, 2);
            reporter.poll();
            wall.advance(100 * MS);
        }
        List<String> during = lines();
        // lines at 0, 1, 3, 7, 15 and 23 s: the wait doubles from 1 s up to 8 s
        assertEquals(6, during.size(), "lines in 30 s of steady misses: " + during);
        assertTrue(during.get(2).contains("planner: 40 deadline misses in the last 2.0 s, last detected"), during.get(2));
        assertTrue(during.get(5).contains("in the last 8.0 s"), "the longest wait: " + during.get(5));
        reporter.close();
        assertEquals(600, countOf(lines(), "planner", "deadline miss"), "what was held back is printed at the end");
    }

    @Test
    void afterACalmSpellTheNextLineComesAtOnceAndTheWaitStartsOver() {
        for (int poll = 0; poll < 80; poll++) { // 8 s of misses: lines at 0, 1, 3 and 7 s
            misses(planner, 1);
            reporter.poll();
            wall.advance(100 * MS);
        }
        assertEquals(4, lines().size(), lines().toString());
        for (int poll = 0; poll < 200; poll++) { // 20 s without a miss: the last held-back miss, then nothing
            reporter.poll();
            wall.advance(100 * MS);
        }
        int calm = lines().size();
        misses(planner, 1);
        reporter.poll();
        assertEquals(calm + 1, lines().size(), "a miss after a calm spell is printed at once");
        misses(planner, 1);
        wall.advance(1000 * MS);
        reporter.poll();
        assertEquals(calm + 2, lines().size(), "and the next a second later: the wait started over");
    }

    @Test
    void theLimitIsPerTask() {
        misses(planner, 1);
        reporter.poll();
        misses(mapper, 2);
        reporter.poll();
        assertEquals(2, lines().size(), "another task's line is not held back by the planner's: " + lines());
        assertTrue(lines().get(1).startsWith("[rtaware] mapper: 2 deadline misses"), lines().get(1));
    }

    @Test
    void noCountIsDroppedWhateverTheRate() {
        long total = 0;
        for (int second = 0; second < 5; second++) {
            for (int poll = 0; poll < 10; poll++) {
                misses(planner, 7);
                reporter.onStaleRun(planner, 0);
                reporter.onTaskError(planner, new IllegalStateException("boom"), ErrorPolicy.CONTINUE, 0);
                total += 7;
                wall.advance(100 * MS);
                reporter.poll();
            }
        }
        reporter.close();
        assertTrue(lines().size() <= 6, "at most one line per second (+ the flush), got " + lines().size());
        assertEquals(total, countOf(lines(), "planner", "deadline miss"), "every miss counted in some line");
        assertEquals(50, countOf(lines(), "planner", "stale run"), "every stale run counted");
        assertEquals(50, countOf(lines(), "planner", "error"), "every error counted");
        assertTrue(lines().get(lines().size() - 1).contains("last: IllegalStateException: boom"),
                "an error line names the exception: " + lines().get(lines().size() - 1));
    }

    /** A reporter of {@code n} tasks named t0, t1, ... (replaces the two-task one). */
    private List<TaskInfo> manyTasks(int n) {
        List<TaskInfo> many = new java.util.ArrayList<>();
        for (int i = 0; i < n; i++) {
            many.add(task("t" + i, i));
        }
        reporter = new ConsoleReporter(new PrintStream(buffer, true, StandardCharsets.UTF_8), many, true, wall, false);
        return many;
    }

    private static long foldedMisses(List<String> lines) {
        return sumOf(lines, Pattern.compile("\\] \\d+ more tasks?: (\\d+) deadline miss"));
    }

    private long allMisses(List<TaskInfo> many) {
        long sum = foldedMisses(lines());
        for (TaskInfo t : many) {
            sum += countOf(lines(), t.name(), "deadline miss");
        }
        return sum;
    }

    @Test
    void aFloodOfTasksGetsTenTaskLinesAndOneLineForTheRest() {
        List<TaskInfo> many = manyTasks(25);
        long total = 0;
        for (TaskInfo t : many) {
            misses(t, t.index() + 1);
            total += t.index() + 1;
        }
        reporter.poll();
        List<String> lines = lines();
        assertEquals(ConsoleReporter.TASK_LINES_PER_SECOND + 1, lines.size(), "10 task lines and one fold: " + lines);
        for (int i = 0; i < ConsoleReporter.TASK_LINES_PER_SECOND; i++) {
            assertTrue(lines.get(i).startsWith("[rtaware] t" + i + ": " + (i + 1) + " deadline miss"), lines.get(i));
        }
        assertEquals("[rtaware] 15 more tasks: " + (total - 55) + " deadline misses; most misses: t24, 25 (at most "
                + ConsoleReporter.TASK_LINES_PER_SECOND + " task lines a second; each task's counts are in the summary)",
                lines.get(ConsoleReporter.TASK_LINES_PER_SECOND));
        assertEquals(total, allMisses(many), "every miss counted in some line");
    }

    @Test
    void theFoldLineComesAtMostOnceASecondAndFlushPrintsWhatIsLeft() {
        List<TaskInfo> many = manyTasks(25);
        long total = 0;
        for (int round = 0; round < 3; round++) {
            for (TaskInfo t : many) {
                misses(t, 2);
                total += 2;
            }
            wall.advance(400 * MS);
            reporter.poll();
        }
        // Round 0 printed 10 task lines and a fold line; rounds 1 and 2 (0.4 and 0.8 s later) find
        // no task due again (each task waits a second) and the fold line not due either.
        assertEquals(11, lines().size(), lines().toString());
        wall.advance(300 * MS);
        reporter.poll();
        assertEquals(22, lines().size(), "a second after the first, 10 task lines and a fold line again: " + lines());
        assertTrue(lines().get(21).startsWith("[rtaware] 15 more tasks: 60 deadline misses;"), lines().get(21));
        for (TaskInfo t : many) {
            misses(t, 1);
            total += 1;
        }
        reporter.flush();
        assertEquals(33, lines().size(), "the flush: 10 task lines and the fold line at once: " + lines());
        assertEquals(total, allMisses(many), "every miss counted in some line");
    }

    @Test
    void aFoldLineCountsEveryKindAndSaysOneTaskInTheSingular() {
        List<TaskInfo> many = manyTasks(ConsoleReporter.TASK_LINES_PER_SECOND + 1);
        for (TaskInfo t : many) {
            reporter.onStaleRun(t, 0);
        }
        TaskInfo last = many.get(many.size() - 1);
        reporter.onExpiredInput(last, "scan", 3 * MS, MS, 0);
        reporter.onTaskError(last, new IllegalStateException("boom"), ErrorPolicy.CONTINUE, 0);
        reporter.poll();
        assertEquals("[rtaware] 1 more task: 1 stale run, 1 expired read, 1 error (at most "
                + ConsoleReporter.TASK_LINES_PER_SECOND + " task lines a second; each task's counts are in the summary)",
                lines().get(lines().size() - 1));
    }

    @Test
    void aPollLooksOnlyAtTasksWithEventsYetHeldBackCountsAndCalmSpellsAreKept() {
        List<TaskInfo> many = manyTasks(130);
        TaskInfo late = many.get(129);
        misses(late, 1);
        reporter.poll();
        assertEquals(List.of("[rtaware] t129: 1 deadline miss, last detected at t=0.150s (deadline t=0.100s)"), lines());
        misses(late, 2);
        wall.advance(500 * MS);
        reporter.poll();
        assertEquals(1, lines().size(), "held back: its next line waits a second");
        wall.advance(600 * MS);
        reporter.poll();
        assertEquals(2, lines().size(), "printed without a new event: " + lines());
        assertTrue(lines().get(1).startsWith("[rtaware] t129: 2 deadline misses"), lines().get(1));
        for (int poll = 0; poll < 30; poll++) { // 3 s of polls without an event: a calm spell
            wall.advance(100 * MS);
            reporter.poll();
        }
        misses(late, 1);
        reporter.poll();
        misses(late, 1);
        wall.advance(1000 * MS);
        reporter.poll();
        assertEquals(4, lines().size(), "after the calm spell, at once and then a second later: " + lines());
    }
}
