package io.rtaware.core.analysis;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import java.util.ArrayList;
import java.util.List;

/**
 * Adds the analysis sections to a report document: {@code advice} (one
 * {@link io.rtaware.core.analysis.PeriodAdvice} per periodic task), {@code schedulability} (a
 * {@link io.rtaware.core.analysis.SchedulabilityReport} of the run's periods) and
 * {@code schedulability_suggested} (the same of the suggested periods). Every command that
 * writes or prints a report calls {@link #enrich} so they all agree. The advice reads the
 * report's {@code conditions}: when the machine was busy or disturbed, a longer period that rests
 * on execution times is not suggested ({@link io.rtaware.core.analysis.PeriodAdvisor}).
 * Stateless and thread-safe.
 */
public final class ReportSections {

    /** Name of the advice section in {@code report.json}. */
    public static final String ADVICE = "advice";
    /** Name of the adaptive period history section in {@code report.json}. */
    public static final String PERIOD_HISTORY = "period_history";
    /** Name of the schedulability section in {@code report.json}. */
    public static final String SCHEDULABILITY = "schedulability";
    /** Name of the section with the schedulability of the suggested periods in {@code report.json}. */
    public static final String SCHEDULABILITY_SUGGESTED = "schedulability_suggested";

    private ReportSections() {
    }

    /**
     * @param report a finished run
     * @param cores the cores the tasks may use (e.g. {@code Runtime.getRuntime().availableProcessors()})
     * @param machine the run's machine verdict, or null when unknown
     * @return the advice and schedulability of the run
     */
    public static Analysis analyze(Report report, int cores, MachineVerdict machine) {
        Advice advice = PeriodAdvisor.advise(report, cores, machine);
        // With no period changed the suggested set is the run's: one analysis, not two (10 000 tasks take seconds).
        return new Analysis(advice, advice.changedPeriodsMs().isEmpty() ? advice.suggestedSet()
                : Schedulability.analyze(report, cores));
    }

    /**
     * Analyzes the document's report, with the machine verdict of its {@code conditions}, and
     * adds (or replaces) its {@code advice}, {@code schedulability} and
     * {@code schedulability_suggested} sections.
     *
     * @param doc the document to write
     * @param cores the cores the tasks may use
     * @return the analysis, for printing with {@link Analysis#text()}
     */
    public static Analysis enrich(ReportDocument doc, int cores) {
        Analysis analysis = analyze(doc.report(), cores, machine(doc));
        doc.section(ADVICE, analysis.advice().tasks());
        doc.section(SCHEDULABILITY, analysis.schedulability());
        doc.section(SCHEDULABILITY_SUGGESTED, analysis.advice().suggestedSet());
        return analysis;
    }

    /**
     * @param doc a run's document, made by the run or read from its report.json
     * @return the machine verdict of its {@code conditions} section, or null when it has none
     *     (a report written before rtaware recorded conditions)
     */
    public static MachineVerdict machine(ReportDocument doc) {
        Object conditions = doc.sections().get(Conditions.SECTION);
        if (conditions instanceof Conditions c) {
            return new MachineVerdict(c.machine(), c.machineReasons(), "");
        }
        if (conditions instanceof JsonNode node && node.path("machine").isTextual()) {
            List<String> reasons = new ArrayList<>();
            node.path("machine_reasons").forEach(r -> reasons.add(r.asText()));
            return new MachineVerdict(node.path("machine").asText(), reasons, "");
        }
        return null;
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
