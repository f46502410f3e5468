package io.rtaware.app.analyze;

import com.code_intelligence.jazzer.junit.FuzzTest;
import io.rtaware.core.report.ReportChecks;
import io.rtaware.core.analysis.ReportSections;
import io.rtaware.core.report.ReportDocument;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

/**
 * Coverage-guided fuzzing of what {@code rtaware analyze} does with a report.json (issue 24), the
 * command's own steps without its picocli shell: reading (whose every failure the command turns
 * into the user's one line), {@link ReportChecks#check} (which may refuse only with an
 * {@link IllegalArgumentException}, the user's one line), then the period advice and schedulability, which must not fail on any
 * report the check let through. Without {@code JAZZER_FUZZ=1} it replays the corpus in
 * {@code AnalyzeFuzzTestInputs/}, seeded from a real run's report.
 */
class AnalyzeFuzzTest {

    private static Path file;

    @BeforeAll
    static void folder() throws IOException {
        file = Files.createTempDirectory("analyze-fuzz").resolve("report.json");
    }

    @AfterAll
    static void removeFolder() throws IOException {
        Files.deleteIfExists(file);
        Files.delete(file.getParent());
    }

    @FuzzTest(maxDuration = "20s")
    void aReportIsRefusedInOneLineOrAnalyzed(byte[] input) throws IOException {
        Files.write(file, input);
        ReportDocument doc;
        try {
            doc = ReportDocument.read(file);
        } catch (IOException | RuntimeException refused) {
            return; // AnalyzeCommand: "cannot read report FILE: ..." in one line
        }
        try {
            ReportChecks.check(doc.report(), file);
        } catch (IllegalArgumentException refused) {
            return;
        }
        ReportSections.analyze(doc.report(), 2, null).text();
    }
}
