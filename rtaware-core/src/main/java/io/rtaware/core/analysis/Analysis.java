package io.rtaware.core.analysis;

import java.util.List;

/**
 * Advice and schedulability of one run, as added to the report and printed. Immutable.
 *
 * @param advice the period advice, with the check of the suggested set
 * @param schedulability the schedulability analysis of the run's periods
 */
public record Analysis(Advice advice, SchedulabilityReport schedulability) {

    /** @return the advice block followed by the schedulability block, as printed */
    public String text() {
        return AnalysisText.advice(advice) + "\n" + AnalysisText.schedulability(schedulability);
    }
}
