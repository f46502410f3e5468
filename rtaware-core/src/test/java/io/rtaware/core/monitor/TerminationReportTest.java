package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.core.report.SummaryTable;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Termination: terminate() on every task, the report to the handlers, and the report's JSON schema. */
class TerminationReportTest {

    private static final Key<Counter> OUT = Counter.key("a.out");

    /** framework_errors: issue 13's count of contained framework faults (an addition, not a rename). */
    private static final Set<String> ROOT_FIELDS =
            Set.of("schema", "time_scale", "duration_s", "misses_total_pct", "tasks", "data", "framework_errors");
    private static final Set<String> TASK_FIELDS = Set.of("name", "schedule", "period_ms", "deadline_ms", "releases",
            "runs", "misses", "miss_pct", "skipped", "stale_runs", "errors", "exec_us", "lateness_us");
    /**
     * Not in issue 2's schema, additions rather than renames: the count of reads older than a
     * declared max age, (issue 13) of listener faults on the task's events, and (issue 16) the
     * periodic tasks' offset, which the released_together advice groups by.
     */
    private static final Set<String> TASK_EXTRA_FIELDS = Set.of("expired_reads", "listener_errors", "offset_ms");
    /** Issue 16 added p999 (the 99.9th percentile) after the older keys, which stay. */
    private static final Set<String> PERCENTILE_FIELDS = Set.of("p50", "p90", "p99", "max", "mean", "p999");
    private static final Set<String> DATA_FIELDS =
            Set.of("name", "producer", "consumers", "commits", "rate_hz", "interval_ms");
    private static final Set<String> INTERVAL_FIELDS = Set.of("min", "mean", "max");

    private final ManualClock clock = new ManualClock();
    private final RecordingListener events = new RecordingListener();
    private FnTask a;
    private FnTask b;

    /** a: 10 ms period, 2 ms work, publishes a.out; b: 20 ms period, consumes a.out, overruns once by 25 ms. */
    private Monitor twoTasks() {
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        a = new FnTask(s -> out[0] = s.produce(OUT), now -> {
            clock.advance(ms(2));
            out[0].publish();
        });
        int[] cycles = {0};
        b = new FnTask(s -> s.consume(OUT), now -> {
            if (cycles[0]++ == 1) {
                clock.advance(ms(25));
            }
        });
        return Monitor.builder(clock).listener(events)
                .task("a", Schedule.periodic(ms(10)), a)
                .task("b", Schedule.periodic(ms(20)), b).build();
    }

    private static Set<String> fieldNames(JsonNode node) {
        Set<String> names = new TreeSet<>();
        for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
            names.add(it.next());
        }
        return names;
    }

    @Test
    void theTasksStoppedHandlersRunOnceAfterEveryTerminateAndBeforeTheReportIsBuilt() {
        Monitor monitor = twoTasks();
        List<String> order = new ArrayList<>();
        monitor.onTasksStopped(() -> order.add("stopped after " + (a.terminations + b.terminations) + " terminations"));
        monitor.onTasksStopped(() -> {
            throw new IllegalStateException("a faulty handler");
        });
        monitor.onTasksStopped(() -> order.add("the next handler"));
        monitor.onTermination(report -> order.add("report"));
        monitor.startStepped().runUntil(ms(100));

        monitor.stop();
        monitor.stop();

        assertEquals(List.of("stopped after 2 terminations", "the next handler", "report"), order);
        assertEquals(1, monitor.frameworkErrors(), "the faulty handler is reported and the stop goes on");
    }

    @Test
    void stopTerminatesEveryTaskOnceAndHandsTheReportToTheHandlers() {
        Monitor monitor = twoTasks();
        List<Report> handled = new ArrayList<>();
        monitor.onTermination(handled::add);
        monitor.startStepped().runUntil(ms(1000));

        Report report = monitor.stop();

        assertEquals(1, a.terminations, "terminate() called on a");
        assertEquals(1, b.terminations, "terminate() called on b");
        assertEquals(List.of(report), handled, "the handler receives the report stop() returns");
        assertEquals(1, events.count("state a TERMINATED"), "a reported TERMINATED");
        assertEquals(1, events.count("state b TERMINATED"), "b reported TERMINATED");
        assertTrue(monitor.isTerminated(), "terminated");

        assertSame(report, monitor.stop(), "stop() again returns the same report");
        assertEquals(1, a.terminations, "terminate() is not called twice");
        assertEquals(1, handled.size(), "handlers are not called twice");
    }

    @Test
    void reportHoldsTheRunsCountsAndDuration() {
        Monitor monitor = twoTasks();
        monitor.startStepped().runUntil(ms(1000));
        Report report = monitor.stop();

        assertEquals(Report.SCHEMA, report.schema(), "schema");
        assertEquals(1.0, report.timeScale(), 0.0, "a manual clock has time scale 1");
        assertEquals(1.0, report.durationS(), 0.0, "one second of world time");
        // b's cycle released at 20 ms starts at 22 ms (after a's) and ends at 47 ms: a miss, and
        // the 40 ms release is skipped. Releases at 0..980 ms: 50.
        assertEquals(50, report.task("b").releases(), "b releases");
        assertEquals(1, report.task("b").skipped(), "b skipped the 40 ms release");
        assertEquals(2, report.task("b").misses(), "b misses");
        assertEquals(4.0, report.task("b").missPct(), 0.0, "b miss_pct = 100 * 2 / 50");
        assertEquals(100, report.task("a").releases(), "a releases");
        long totalMisses = report.task("a").misses() + report.task("b").misses();
        assertEquals(Math.round(100.0 * totalMisses / 150 * 100) / 100.0, report.missesTotalPct(), 0.0,
                "misses_total_pct is over all tasks' releases");
        assertEquals(10.0, report.task("a").periodMs(), "period_ms");
        assertEquals(10.0, report.task("a").deadlineMs(), "deadline_ms");
        assertEquals(2000.0, report.task("a").execUs().p50(), 20.0, "exec p50 about 2 ms (histogram precision)");
        assertEquals(2000.0, report.task("a").execUs().mean(), 0.0, "exec mean exactly 2 ms");
        assertEquals(List.of("b"), report.key("a.out").consumers(), "consumers of a.out");
    }

    @Test
    void reportJsonHasExactlyTheSchemaFieldNames() {
        Monitor monitor = twoTasks();
        monitor.startStepped().runUntil(ms(100));
        JsonNode json = new ReportDocument(monitor.stop()).toJson();

        assertEquals(new TreeSet<>(ROOT_FIELDS), fieldNames(json), "root fields");
        assertEquals("rtaware.report/1", json.get("schema").asText(), "schema value");
        Set<String> taskFields = new TreeSet<>(TASK_FIELDS);
        taskFields.addAll(TASK_EXTRA_FIELDS);
        for (JsonNode task : json.get("tasks")) {
            assertEquals(taskFields, fieldNames(task), "fields of task " + task.get("name"));
            assertEquals(new TreeSet<>(PERCENTILE_FIELDS), fieldNames(task.get("exec_us")), "exec_us fields");
            assertEquals(new TreeSet<>(PERCENTILE_FIELDS), fieldNames(task.get("lateness_us")), "lateness_us fields");
        }
        assertEquals(2, json.get("tasks").size(), "one entry per task");
        for (JsonNode data : json.get("data")) {
            assertEquals(new TreeSet<>(DATA_FIELDS), fieldNames(data), "fields of key " + data.get("name"));
            assertEquals(new TreeSet<>(INTERVAL_FIELDS), fieldNames(data.get("interval_ms")), "interval_ms fields");
        }
        assertEquals("periodic", json.get("tasks").get(0).get("schedule").asText(), "schedule value");
        assertTrue(json.get("tasks").get(0).get("releases").isIntegralNumber(), "releases is an integer");
        assertTrue(json.get("data").get(0).get("consumers").isArray(), "consumers is an array");
    }

    @Test
    void reportRoundTripsThroughReportDocumentWithSections(@TempDir Path dir) throws IOException {
        Monitor monitor = Monitor.builder(clock)
                .task("boot", Schedule.once(), FnTask.of(now -> { }))
                .task("a", Schedule.periodic(ms(10)), twoTasksProducer()).build();
        monitor.startStepped().runUntil(ms(100));
        Report report = monitor.stop();
        Path file = dir.resolve("out/report.json");

        new ReportDocument(report).section("run", Map.of("seed", 42)).write(file);
        ReportDocument read = ReportDocument.read(file);

        assertEquals(report, read.report(), "the core report survives JSON unchanged");
        assertEquals(42, ((JsonNode) read.sections().get("run")).get("seed").asInt(), "sections come back as JSON");
        assertEquals(null, read.report().task("boot").periodMs(), "a once task has no period");
    }

    private FnTask twoTasksProducer() {
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        return new FnTask(s -> out[0] = s.produce(OUT), now -> out[0].publish());
    }

    @Test
    void readingAFileThatIsNotAReportNamesTheFile(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("other.json");
        Files.writeString(file, "{\"schema\": \"something/2\"}");
        IOException e = assertThrows(IOException.class, () -> ReportDocument.read(file));
        assertTrue(e.getMessage().startsWith(file.toString()), "the message names the file: " + e.getMessage());
    }

    @Test
    void summaryTableListsEveryTaskAndKey() {
        Monitor monitor = twoTasks();
        monitor.startStepped().runUntil(ms(1000));
        String table = SummaryTable.format(monitor.stop());

        assertTrue(table.lines().anyMatch(l -> l.startsWith("a ") && l.contains("periodic") && l.contains(" 100 ")),
                "a row for task a with its 100 releases:\n" + table);
        assertTrue(table.lines().anyMatch(l -> l.startsWith("b ") && l.contains(" 50 ")), "a row for task b:\n" + table);
        assertTrue(table.lines().anyMatch(l -> l.startsWith("a.out ") && l.contains("b")), "a row for key a.out:\n" + table);
        assertTrue(table.startsWith("rtaware summary: 1.000 s of world time"), "headline:\n" + table);
    }

    @Test
    void stopBeforeStartStillTerminatesTasksAndReports() {
        Monitor monitor = twoTasks();
        Report report = monitor.stop();
        assertEquals(0, report.task("a").releases(), "nothing ran");
        assertEquals(0.0, report.missesTotalPct(), 0.0, "no releases, no miss percentage");
        assertEquals(1, a.terminations, "terminate() still called");
        assertThrows(IllegalStateException.class, monitor::startStepped, "a stopped monitor cannot start");
    }
}
