package io.rtaware.app.report;

import io.rtaware.core.analysis.PeriodAdvisor;
import io.rtaware.core.analysis.Schedulability;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;

/**
 * Adds the analysis sections to a report document: {@code advice} (a list of
 * {@link io.rtaware.core.analysis.AdviceItem}) and {@code schedulability} (a
 * {@link io.rtaware.core.analysis.SchedulabilityReport}). Every command that writes or prints a
 * report calls {@link #enrich} so they all agree. Stateless and thread-safe.
 */
public final class ReportSections {

    /** Name of the advice section in {@code report.json}. */
    public static final String ADVICE = "advice";
    /** Name of the adaptive period history section in {@code report.json}. */
    public static final String PERIOD_HISTORY = "period_history";
    /** Name of the schedulability section in {@code report.json}. */
    public static final String SCHEDULABILITY = "schedulability";

    private ReportSections() {
    }

    /**
     * @param report a finished run
     * @param cores the machine's core count (e.g. {@code Runtime.getRuntime().availableProcessors()})
     * @return the advice and schedulability of the run
     */
    public static Analysis analyze(Report report, int cores) {
        return new Analysis(PeriodAdvisor.advise(report), Schedulability.analyze(report, cores));
    }

    /**
     * Analyzes the document's report and adds (or replaces) its {@code advice} and
     * {@code schedulability} sections.
     *
     * @param doc the document to write
     * @param cores the machine's core count
     * @return the analysis, for printing with {@link Analysis#text()}
     */
    public static Analysis enrich(ReportDocument doc, int cores) {
        Analysis analysis = analyze(doc.report(), cores);
        doc.section(ADVICE, analysis.advice());
        doc.section(SCHEDULABILITY, analysis.schedulability());
        return analysis;
    }

    /**
     * Adds the {@code period_history} section when the monitor has tasks with a period range.
     *
     * @param doc the document to write
     * @param monitor a monitor whose task threads have stopped (e.g. in a termination handler)
     * @return the text to print after the summary, or "" when no task is adaptive
     */
    public static String addPeriodHistory(ReportDocument doc, io.rtaware.core.monitor.Monitor monitor) {
        java.util.List<PeriodHistory> histories = PeriodHistory.of(monitor);
        if (histories.isEmpty()) {
            return "";
        }
        doc.section(PERIOD_HISTORY, histories);
        return PeriodHistory.text(histories);
    }
}
