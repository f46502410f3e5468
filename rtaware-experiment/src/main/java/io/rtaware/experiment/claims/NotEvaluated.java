package io.rtaware.experiment.claims;

/**
 * A claim the runs the summary uses cannot decide.
 *
 * @param id the claim's stable id, as {@link Claim#id()}
 * @param claim what the paper says
 * @param reason which data is missing
 * @param verdictAllRuns the verdict on all runs, busy ones included ({@link Verdict#json()}), or
 *     {@code not_evaluated}
 * @param fragile true when all runs do decide it: the exclusion of runs left it undecided
 */
public record NotEvaluated(String id, String claim, String reason, String verdictAllRuns, boolean fragile) {

    /** The verdict of a claim that has none, as {@code verdict_all_runs} and in the docs' quotes. */
    public static final String NOT_EVALUATED = "not_evaluated";

    /**
     * @param allRuns the verdict on all runs
     * @return this claim with that verdict beside it
     */
    NotEvaluated onAllRuns(String allRuns) {
        return new NotEvaluated(id, claim, reason, allRuns, !NOT_EVALUATED.equals(allRuns));
    }
}
