package io.rtaware.experiment.claims;

/**
 * One family of claims: its stable id, the words it judges, and how it judges them. A family
 * judged per course or top speed gives one verdict per scope, each under {@code id()} and the
 * scope's suffix ({@code slow-hits-on-office@0.4mps}); the id is never read back from the words.
 */
interface ClaimRule {

    /** @return the family's stable id, e.g. {@code slow-hits} */
    String id();

    /** @return what the paper (or, for rtaware's own rules, the rule) says, in one sentence */
    String statement();

    /**
     * Adds this family's verdicts, or the reason it has none, to the judging.
     *
     * @param j the results and where the verdicts go
     */
    void judge(Judging j);
}
