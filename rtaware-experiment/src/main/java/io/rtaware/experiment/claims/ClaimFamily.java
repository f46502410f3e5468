package io.rtaware.experiment.claims;

/** A {@link ClaimRule} whose id and words are fixed when it is made; subclasses give the judging. */
abstract class ClaimFamily implements ClaimRule {

    private final String id;
    private final String statement;

    /**
     * @param id the family's stable id
     * @param statement what the paper (or the rule) says
     */
    ClaimFamily(String id, String statement) {
        this.id = id;
        this.statement = statement;
    }

    @Override
    public final String id() {
        return id;
    }

    @Override
    public final String statement() {
        return statement;
    }
}
