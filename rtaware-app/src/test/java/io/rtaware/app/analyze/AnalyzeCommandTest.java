package io.rtaware.app.analyze;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.app.RtawareCli;
import io.rtaware.core.analysis.ReportSections;
import io.rtaware.core.report.DataReport;
import io.rtaware.core.report.Percentiles;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.core.report.TaskReport;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AnalyzeCommandTest {

    @TempDir
    Path dir;

    private static Report chainReport() {
        Percentiles aExec = new Percentiles(2000, 2000, 2100, 2500, 2000);
        Percentiles bExec = new Percentiles(20000, 20000, 20500, 21000, 20000);
        return new Report(Report.SCHEMA, 1.0, 5.0, 0.0, List.of(
                new TaskReport("a", "periodic", 10.0, 10.0, 500, 500, 0, 0, 0, 0, 0, 0, aExec, Percentiles.EMPTY),
                new TaskReport("b", "periodic", 50.0, 50.0, 100, 100, 0, 0, 0, 0, 0, 0, bExec, Percentiles.EMPTY)),
                List.of(new DataReport("a.out", "a", List.of("b"), 500, 100.0, new DataReport.Interval(10, 10, 10)),
                        new DataReport("b.out", "b", List.of(), 100, 20.0, new DataReport.Interval(50, 50, 50))));
    }

    private static String[] run(String... args) {
        PrintStream out = System.out;
        PrintStream err = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
        System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
        int status;
        try {
            status = RtawareCli.execute(args);
        } finally {
            System.setOut(out);
            System.setErr(err);
        }
        return new String[] {Integer.toString(status), o.toString(StandardCharsets.UTF_8),
                e.toString(StandardCharsets.UTF_8)};
    }

    @Test
    void enrichWritesSectionsAndAnalyzePrintsTheSameFromTheSavedFile() throws Exception {
        ReportDocument doc = new ReportDocument(chainReport());
        String printed = ReportSections.enrich(doc, 2).text();
        Path file = dir.resolve("report.json");
        doc.write(file);

        JsonNode root = ReportDocument.mapper().readTree(file.toFile());
        JsonNode b = root.path("advice").get(1);
        assertEquals("b", b.path("task").asText());
        assertEquals("infeasible", b.path("verdict").asText());
        assertEquals(20.5, b.path("suggested_period_ms").asDouble(), "never below b's 20.5 ms of work (p99)");
        assertEquals(20.5, b.path("lower_ms").asDouble());
        assertEquals(5.0, b.path("upper_ms").asDouble());
        assertEquals("sampling", b.path("bounds").get(2).path("rule").asText());
        assertEquals(100.0, b.path("bounds").get(2).path("evidence").path("input_rate_hz").asDouble());
        assertEquals(2, root.path("schedulability").path("cores").asInt());
        assertEquals(0.62, root.path("schedulability").path("utilization_p99").asDouble(), 1e-9);
        assertTrue(root.path("schedulability").path("rta_schedulable_p99").asBoolean());
        assertTrue(root.path("schedulability_suggested").path("rta_schedulable_p99_on_cores").asBoolean());

        String[] result = run("analyze", file.toString(), "--cores", "2");
        assertEquals("0", result[0], result[2]);
        assertEquals("machine: not recorded (a report written before rtaware recorded its run's conditions): the advice"
                + " cannot tell the machine's share from the tasks'" + System.lineSeparator() + printed, result[1]);
    }

    /**
     * Issue 26: analyze applies the saved run's machine verdict as the run did: a task whose
     * execution time nears its period on a busy machine is not told to lengthen it.
     */
    @Test
    void aSavedBusyRunGetsNoAdviceThatBlamesATaskForTheMachine() throws Exception {
        Percentiles exec = new Percentiles(8000, 9000, 9500, 9900, 8500, 9800);
        Report report = new Report(Report.SCHEMA, 1.0, 5.0, 0.0, List.of(
                new TaskReport("heavy", "periodic", 10.0, 10.0, 500, 500, 0, 0, 0, 0, 0, 0, exec, Percentiles.EMPTY)),
                List.of());
        Path quiet = dir.resolve("quiet.json");
        new ReportDocument(report).write(quiet);
        String[] alone = run("analyze", quiet.toString());
        assertEquals("0", alone[0], alone[2]);
        assertTrue(alone[1].contains("heavy            10ms -> 13.6ms   lengthen   'heavy' 10 ms -> 13.6 ms: its exec"
                + " p99 9.5 ms is 95% of its deadline, no headroom"), alone[1]);

        Path busy = dir.resolve("busy.json");
        JsonNode root = ReportDocument.mapper().readTree(quiet.toFile());
        ((com.fasterxml.jackson.databind.node.ObjectNode) root).set("conditions", ReportDocument.mapper().readTree(
                "{\"machine\": \"busy\", \"machine_reasons\": [\"other processes used 1.6 of 2 CPUs (more than 0.10)\"]}"));
        ReportDocument.mapper().writeValue(busy.toFile(), root);
        String[] r = run("analyze", busy.toString());
        assertEquals("0", r[0], r[2]);
        assertTrue(r[1].startsWith("machine: busy (other processes used 1.6 of 2 CPUs (more than 0.10))"), r[1]);
        assertTrue(r[1].contains("heavy            10ms -> 10ms     machine    'heavy' keeps 10 ms: the run's figures"
                + " ask for at least 9.5 ms by exec p99, but the machine was busy"), r[1]);
    }

    @Test
    void neitherAReportNorARecordingIsOneLineWithStatus2() {
        String[] r = run("analyze");
        assertEquals("2", r[0]);
        assertEquals("rtaware: give a report.json, a recording (--verify FILE.mcap), or both", r[2].strip());
    }

    @Test
    void badFileIsOneLineWithStatus2() throws Exception {
        Path bad = dir.resolve("bad.json");
        Files.writeString(bad, "{\"schema\": \"something-else\"}");
        String[] result = run("analyze", bad.toString());
        assertEquals("2", result[0]);
        assertEquals(1, result[2].strip().lines().count(), result[2]);
        assertTrue(result[2].contains("not an rtaware report"), result[2]);

        String[] missing = run("analyze", dir.resolve("missing.json").toString());
        assertEquals("2", missing[0]);
        assertEquals(1, missing[2].strip().lines().count(), missing[2]);
    }

    /**
     * Issue 24: tasks of 100 ns periods released together divided by zero in the advice; the
     * saved report of such a run is analyzed with exit 0 and no stack trace.
     */
    @Test
    void aReportOfSubMicrosecondPeriodsIsAnalyzed() throws Exception {
        Percentiles exec = new Percentiles(50, 60, 70, 80, 55);
        Percentiles late = new Percentiles(100, 500, 600, 700, 200);
        List<TaskReport> tasks = new java.util.ArrayList<>();
        for (int i = 0; i < 4; i++) {
            tasks.add(new TaskReport("t" + i, "periodic", 0.0001, 0.0001, 0.0, 1000, 1000, 10, 1.0, 0, 0, 0, 0, exec,
                    late, 0, null, null));
        }
        Path file = dir.resolve("report.json");
        new ReportDocument(new Report(Report.SCHEMA, 1.0, 1.0, 0.0, tasks, List.of())).write(file);
        String[] r = run("analyze", file.toString());
        assertEquals("0", r[0], "stderr: " + r[2]);
        assertEquals("", r[2], "no stack trace");
        assertTrue(r[1].contains("released_together"), r[1]);
    }
}
