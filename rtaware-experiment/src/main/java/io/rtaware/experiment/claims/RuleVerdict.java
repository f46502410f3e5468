package io.rtaware.experiment.claims;

/**
 * One of rtaware's own rules (not the paper's) checked against the runs: the {@code rules} of
 * {@code summary.json}, apart from the paper's claims. A rule the runs cannot test is listed with
 * the verdict {@link #NOT_EVALUATED} and the reason in {@code evidence}, never as holding.
 *
 * @param id the rule's stable id with its scope, e.g. {@code reaction-rule-bound-on-office@0.4mps}
 * @param rule what the rule says (with the course and top speed it was checked on)
 * @param verdict {@link #HOLDS}, {@link #FAILS}, {@link #MIXED} or {@link #NOT_EVALUATED}
 * @param evidence the numbers the verdict rests on, or why the rule was not evaluated
 * @param judgedBy how the verdict follows from the numbers; empty when not evaluated
 * @param verdictAllRuns the verdict on all runs, busy ones included
 * @param fragile true when {@code verdictAllRuns} differs from {@code verdict}
 * @param fewestRunsPerCell the fewest runs in any set the verdict rests on, or null when not evaluated
 * @param smallSample true when {@code fewestRunsPerCell} is below {@link PaperClaims#SMALL_SAMPLE_RUNS}
 */
public record RuleVerdict(String id, String rule, String verdict, String evidence, String judgedBy,
                          String verdictAllRuns, boolean fragile, Integer fewestRunsPerCell, boolean smallSample) {

    /** The runs agree with the rule. */
    public static final String HOLDS = "holds";
    /** The runs contradict it. */
    public static final String FAILS = "fails";
    /** The runs agree in part. */
    public static final String MIXED = "mixed";
    /** The runs cannot test it (the evidence says why). */
    public static final String NOT_EVALUATED = NotEvaluated.NOT_EVALUATED;

    static RuleVerdict of(Claim c) {
        return new RuleVerdict(c.id(), c.claim(), word(c.verdict()), c.evidence(), c.rule(), null, false,
                c.fewestRunsPerCell(), c.smallSample());
    }

    static RuleVerdict of(NotEvaluated n) {
        return new RuleVerdict(n.id(), n.claim(), NOT_EVALUATED, n.reason(), "", null, false, null, false);
    }

    private static String word(Verdict v) {
        return switch (v) {
            case REPRODUCED -> HOLDS;
            case NOT_REPRODUCED -> FAILS;
            default -> MIXED;
        };
    }

    RuleVerdict onAllRuns(String allRuns) {
        return new RuleVerdict(id, rule, verdict, evidence, judgedBy, allRuns, !verdict.equals(allRuns),
                fewestRunsPerCell, smallSample);
    }

    /** @return the caveats of the verdict in words; empty when none */
    public String caveats() {
        return Caveats.of(fragile, verdictAllRuns, smallSample, fewestRunsPerCell);
    }
}
