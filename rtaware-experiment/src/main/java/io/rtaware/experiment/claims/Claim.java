package io.rtaware.experiment.claims;

import java.util.List;

/**
 * One claim with its verdict, judged on the runs the summary uses (the quiet ones, unless busy
 * runs are included) and again on all runs, so that leaving runs out cannot change a verdict
 * unseen.
 *
 * @param id the claim's stable id, e.g. {@code table1-set1-faster} or {@code slow-hits@0.5mps}: its
 *     family's id and the scope it was judged on, never derived from its words; docs quote its
 *     verdict by it ({@code claim `FOLDER/ID`: VERDICT})
 * @param claim what the paper says (with the course and top speed it was judged on, when they are
 *     not the paper's)
 * @param verdict what the runs the summary uses say
 * @param evidence the numbers the verdict rests on
 * @param rule how the verdict follows from the numbers
 * @param verdictAllRuns the verdict on all runs, busy ones included: a {@link Verdict#json()} name,
 *     or {@code not_evaluated}
 * @param fragile true when {@code verdictAllRuns} differs from {@code verdict}: the exclusion of
 *     runs decides the verdict
 * @param fewestRunsPerCell the fewest runs (or blocks) in any set the verdict rests on, or null
 * @param smallSample true when {@code fewestRunsPerCell} is below {@link PaperClaims#SMALL_SAMPLE_RUNS}
 * @param family the id of the claim's family, without the scope
 * @param judgedOn the conditions the claim was judged on (course, top speed, swept tasks, CPU quota), by which
 *     verdicts of different experiments under the same conditions are compared
 * @param cells the sets the verdict rests on, each as its periods in task order and its top speed
 *     (e.g. {@code 200/300/500/800 ms at 0.4 m/s}): two experiments contradict each other only where
 *     they judged a claim on a set they share
 */
public record Claim(String id, String claim, Verdict verdict, String evidence, String rule, String verdictAllRuns,
                    boolean fragile, Integer fewestRunsPerCell, boolean smallSample, String family, String judgedOn,
                    List<String> cells) {

    /**
     * Keeps an unmodifiable copy of the cells.
     *
     * @param id the claim's stable id
     * @param claim what the paper says
     * @param verdict what the runs the summary uses say
     * @param evidence the numbers the verdict rests on
     * @param rule how the verdict follows from the numbers
     * @param verdictAllRuns the verdict on all runs
     * @param fragile whether the two verdicts differ
     * @param fewestRunsPerCell the fewest runs in any set the verdict rests on, or null
     * @param smallSample whether that is below the small-sample bound
     * @param family the id of the claim's family
     * @param judgedOn the conditions it was judged on
     * @param cells the sets it rests on; copied
     */
    public Claim {
        cells = List.copyOf(cells);
    }

    /**
     * @param allRuns the verdict on all runs ({@link Verdict#json()} or {@code not_evaluated})
     * @return this claim with that verdict beside its own
     */
    Claim onAllRuns(String allRuns) {
        return new Claim(id, claim, verdict, evidence, rule, allRuns, !verdict.json().equals(allRuns), fewestRunsPerCell,
                smallSample, family, judgedOn, cells);
    }

    /** @return the caveats of the verdict in words, e.g. {@code fragile: on all runs mixed}; empty when none */
    public String caveats() {
        return Caveats.of(fragile, verdictAllRuns, smallSample, fewestRunsPerCell);
    }
}
