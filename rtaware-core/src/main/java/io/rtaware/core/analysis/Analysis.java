package io.rtaware.core.analysis;

import java.util.List;

/**
 * Advice and schedulability of one run, as added to the report and printed. Immutable.
 *
 * @param advice the period advice
 * @param schedulability the schedulability analysis
 */
public record Analysis(List<AdviceItem> advice, SchedulabilityReport schedulability) {

    /**
     * Copies the advice list.
     *
     * @param advice the period advice
     * @param schedulability the schedulability analysis
     */
    public Analysis {
        advice = List.copyOf(advice);
    }

    /** @return the advice block followed by the schedulability block, as printed */
    public String text() {
        return AnalysisText.advice(advice) + "\n" + AnalysisText.schedulability(schedulability);
    }
}
