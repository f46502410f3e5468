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
 */
public record RuleVerdict(String id, String rule, String verdict, String evidence, String judgedBy) {

    /** The runs agree with the rule. */
    public static final String HOLDS = "holds";
    /** The runs contradict it. */
    public static final String FAILS = "fails";
    /** The runs agree in part. */
    public static final String MIXED = "mixed";
    /** The runs cannot test it (the evidence says why). */
    public static final String NOT_EVALUATED = "not_evaluated";

    static RuleVerdict of(Claim c) {
        String verdict = switch (c.verdict()) {
            case REPRODUCED -> HOLDS;
            case NOT_REPRODUCED -> FAILS;
            default -> MIXED;
        };
        return new RuleVerdict(c.id(), c.claim(), verdict, c.evidence(), c.rule());
    }

    static RuleVerdict of(NotEvaluated n) {
        return new RuleVerdict(n.id(), n.claim(), NOT_EVALUATED, n.reason(), "");
    }
}
