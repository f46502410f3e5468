package io.rtaware.core.testing;

/**
 * A requirement found through an environment variable that {@code .ci/run} sets: missing when the
 * variable is unset or blank, or when what it names is not usable.
 */
abstract class VariableRequirement implements Requirement {

    private final String variable;
    private final String what;
    private final String setUp;

    /**
     * @param variable the environment variable
     * @param what what it names, in words ("the Python peers")
     * @param setUp what {@code .ci/run} sets it to, in words
     */
    VariableRequirement(String variable, String what, String setUp) {
        this.variable = variable;
        this.what = what;
        this.setUp = setUp;
    }

    /**
     * @param value the variable's value, not blank
     * @return why it is not usable, or {@code null} when it is
     */
    abstract String unusable(String value);

    /** @return the variable's value, once the rule of {@link Requires} has let the test go on */
    final String required() {
        RequiresExtension.require(this);
        return System.getenv(variable);
    }

    @Override
    public final String name() {
        return what + " (" + variable + ")";
    }

    @Override
    public final String missingReason() {
        String value = System.getenv(variable);
        if (value == null || value.isBlank()) {
            return variable + " is unset (.ci/run sets it to " + setUp + ")";
        }
        String problem = unusable(value);
        return problem == null ? null : variable + "=" + value + " " + problem;
    }
}
