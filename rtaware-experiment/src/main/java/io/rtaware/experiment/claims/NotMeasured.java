package io.rtaware.experiment.claims;

/**
 * A claim no result of this experiment can decide, whatever its sets: always listed as not
 * evaluated, with the reason.
 *
 * @param id the claim's stable id
 * @param statement what the paper says
 * @param reason why no experiment here decides it
 */
record NotMeasured(String id, String statement, String reason) implements ClaimRule {

    @Override
    public void judge(Judging j) {
        j.unjudged(this, Scope.PAPER, reason);
    }
}
