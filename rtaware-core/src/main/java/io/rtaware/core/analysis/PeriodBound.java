package io.rtaware.core.analysis;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One bound on a task's period, from one rule, with its figure. Serialized in snake_case inside
 * an item of the report's {@code advice} section. Immutable.
 *
 * @param rule the rule: lower bounds {@value #EXEC} and {@value #RESPONSE_TIME}; upper bounds
 *     {@value #SAMPLING}, {@value #REACTION} and {@value #FRESHNESS}
 * @param side {@value #LOWER} (the period must be at least {@code ms}) or {@value #UPPER} (at
 *     most {@code ms})
 * @param ms the bound, ms; an upper bound of zero or less means no period satisfies the rule
 * @param label the bound named for a person, with what it is of (e.g. {@code sampling of
 *     'odometry' (15.58 Hz)})
 * @param evidence the figures the bound rests on, by snake_case name with a unit suffix
 */
public record PeriodBound(String rule, String side, double ms, String label, Map<String, Object> evidence) {

    /** Lower bound: the task's p99 execution time must fit in its deadline. */
    public static final String EXEC = "exec";
    /** Lower bound: the task's response time in the whole set, on the cores it may use. */
    public static final String RESPONSE_TIME = "response_time";
    /** Upper bound: sample each input at least twice per change of it. */
    public static final String SAMPLING = "sampling";
    /** Upper bound: react to what the input shows before it is reached. */
    public static final String REACTION = "reaction";
    /** Upper bound: a consumer's declared maximum age of what the task produces. */
    public static final String FRESHNESS = "freshness";
    /** The period must be at least the bound. */
    public static final String LOWER = "lower";
    /** The period must be at most the bound. */
    public static final String UPPER = "upper";

    /**
     * Copies the evidence so the bound stays immutable.
     *
     * @param rule the rule
     * @param side {@value #LOWER} or {@value #UPPER}
     * @param ms the bound, ms
     * @param label the bound named for a person
     * @param evidence the figures the bound rests on
     */
    public PeriodBound {
        evidence = Collections.unmodifiableMap(new LinkedHashMap<>(evidence));
    }

    /** @return true for a lower bound */
    public boolean lower() {
        return LOWER.equals(side);
    }
}
