package io.rtaware.app.analyze;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A report that lacks what the analysis reads, or holds impossible values, is one line and exit status 2. */
class AnalyzeInputTest {

    private static final String EXEC = "\"exec_us\": {\"p50\": 100, \"p90\": 100, \"p99\": 120, \"max\": 150, \"mean\": 100}";

    @TempDir
    Path dir;

    private String analyze(String json) throws Exception {
        Path file = Files.writeString(dir.resolve("r.json"), json);
        return file.toString();
    }

    private static String report(String tasks) {
        return "{\"schema\": \"rtaware.report/1\", \"time_scale\": 1, \"duration_s\": 1, \"misses_total_pct\": 0,"
                + tasks + " \"data\": []}";
    }

    private static String task(String name, String period, String exec) {
        return "{\"name\": \"" + name + "\", \"schedule\": \"periodic\", \"period_ms\": " + period
                + ", \"releases\": 10, \"runs\": 10" + (exec.isEmpty() ? "" : ", " + exec) + "}";
    }

    @Test
    void aReportWithoutTasksIsOneLine() throws Exception {
        CliRun.of("analyze", analyze(report(""))).assertOneLineUserError("has no 'tasks'");
    }

    @Test
    void aTaskWithoutExecutionTimesIsOneLine() throws Exception {
        CliRun.of("analyze", analyze(report("\"tasks\": [" + task("a", "10", "") + "],")))
                .assertOneLineUserError("task 'a' has no 'exec_us'");
    }

    @Test
    void aPeriodTooSmallToBeAPeriodIsOneLine() throws Exception {
        CliRun.of("analyze", analyze(report("\"tasks\": [" + task("a", "1e-300", EXEC) + "],")))
                .assertOneLineUserError("task 'a': 'period_ms' must be");
        CliRun.of("analyze", analyze(report("\"tasks\": [" + task("a", "\"NaN\"", EXEC) + "],")))
                .assertOneLineUserError("task 'a': 'period_ms' must be");
    }

    /** Issue 34: a malformed report printed Jackson's own text (its source dump, Java type names). */
    @Test
    void aMalformedReportIsOneLineNamingTheFileAndWhatIsWrong() throws Exception {
        String truncated = analyze("{\"schema\": \"rtaware.report/1\", \"tasks\": [");
        CliRun r = CliRun.of("analyze", truncated).assertOneLineUserError("report " + truncated + ": not valid JSON at line 1");
        assertFalse(r.err().contains("[Source") || r.err().contains("com.fasterxml"), r.err());
        String wrongType = analyze(report("\"tasks\": [" + task("a", "\"ten\"", EXEC) + "],"));
        r = CliRun.of("analyze", wrongType).assertOneLineUserError("report " + wrongType + ": field 'tasks[0].period_ms' "
                + "does not hold what a report holds there");
        assertFalse(r.err().contains("java.lang") || r.err().contains("Cannot deserialize"), r.err());
        CliRun.of("analyze", dir.resolve("none.json").toString()).assertOneLineUserError("report "
                + dir.resolve("none.json") + " (No such file");
    }

    @Test
    void aWellFormedMinimalReportIsAnalyzed() throws Exception {
        CliRun r = CliRun.of("analyze", analyze(report("\"tasks\": [" + task("a", "10", EXEC) + "],")));
        assertEquals(0, r.status(), r.toString());
        assertTrue(r.out().contains("schedulability"), r.out());
    }
}
