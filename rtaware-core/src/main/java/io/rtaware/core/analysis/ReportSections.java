package io.rtaware.core.analysis;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Adds the analysis sections to a report document: {@code advice} (a list of
 * {@link io.rtaware.core.analysis.AdviceItem}) and {@code schedulability} (a
 * {@link io.rtaware.core.analysis.SchedulabilityReport}). Every command that writes or prints a
 * report calls {@link #enrich} so they all agree. When the report's {@code conditions} say the
 * machine was busy or disturbed, the advice that rests on execution times and lateness (which
 * the machine inflates) does not blame the task: it becomes a {@value #MACHINE_RULE} item that
 * names the machine's figures and keeps the evidence. Stateless and thread-safe.
 */
public final class ReportSections {

    /** Name of the advice section in {@code report.json}. */
    public static final String ADVICE = "advice";
    /** Name of the adaptive period history section in {@code report.json}. */
    public static final String PERIOD_HISTORY = "period_history";
    /** Name of the schedulability section in {@code report.json}. */
    public static final String SCHEDULABILITY = "schedulability";

    /** The rule of an advice item that a busy or disturbed machine turned from blame on a task. */
    public static final String MACHINE_RULE = "machine";

    /** Rules whose evidence (execution time, lateness) another process or a JVM pause inflates. */
    private static final Set<String> MACHINE_SENSITIVE = Set.of("exec_near_period", "released_together");

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
        MachineVerdict verdict = machine(doc);
        String machine = verdict == null ? null : verdict.verdict();
        List<String> reasons = verdict == null ? List.of() : verdict.reasons();
        analysis = new Analysis(onMachine(analysis.advice(), machine, reasons), analysis.schedulability());
        doc.section(ADVICE, analysis.advice());
        doc.section(SCHEDULABILITY, analysis.schedulability());
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
     * @param advice the advice of a run
     * @param machine the run's machine verdict ({@code quiet}, {@code busy}, ...), or null if unknown
     * @param reasons the figures behind the verdict
     * @return the advice, with each item whose evidence the machine inflates turned into a
     *     {@value #MACHINE_RULE} item when the machine was busy or disturbed
     */
    public static List<AdviceItem> onMachine(List<AdviceItem> advice, String machine, List<String> reasons) {
        if (!MachineVerdict.BUSY.equals(machine) && !MachineVerdict.DISTURBED.equals(machine)) {
            return advice;
        }
        List<AdviceItem> out = new ArrayList<>();
        for (AdviceItem item : advice) {
            if (!MACHINE_SENSITIVE.contains(item.rule())) {
                out.add(item);
                continue;
            }
            Map<String, Object> evidence = new LinkedHashMap<>(item.evidence());
            evidence.put("rule_not_applied", item.rule());
            evidence.put("machine", machine);
            out.add(new AdviceItem(item.task(), MACHINE_RULE, item.periodMs(), item.periodMs(), evidence,
                    String.format(Locale.ROOT, "'%s': no %s advice from this run: the machine was %s (%s), which"
                            + " inflates execution times and lateness; re-run on a quiet machine to tell the task's own"
                            + " cost", item.task(), item.rule(), machine, String.join("; ", reasons))));
        }
        return out;
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
