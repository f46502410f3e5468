package io.rtaware.core.report;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.analysis.AnalysisText;
import io.rtaware.core.analysis.Schedulability;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A period of one nanosecond is printed as 1ns in the summary and the analysis, never as 0.ms. */
class TinyPeriodPrintingTest {

    @Test
    void summaryAndScheduleAnalysisPrintOneNanosecond() {
        Percentiles exec = new Percentiles(0.001, 0.001, 0.001, 0.001, 0.001);
        Report report = new Report(Report.SCHEMA, 1.0, 1.0, 0.0, List.of(
                new TaskReport("fast", "periodic", 1e-6, 1e-6, 10, 10, 0, 0, 0, 0, 0, 0, exec, Percentiles.EMPTY)), List.of());
        String table = SummaryTable.format(report);
        assertTrue(table.contains(" 1ns "), table);
        String analysis = AnalysisText.schedulability(Schedulability.analyze(report, 1));
        assertTrue(analysis.contains("1ns"), analysis);
        assertFalse(table.contains(".ms") || analysis.contains(".ms") || analysis.contains(" 0ms"), table + analysis);
    }
}
