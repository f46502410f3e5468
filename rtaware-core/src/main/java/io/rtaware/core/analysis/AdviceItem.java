package io.rtaware.core.analysis;

import java.util.Map;

/**
 * One piece of period advice. Serialized by Jackson in snake_case inside the report's
 * {@code advice} section. Immutable.
 *
 * @param task the task the advice is for
 * @param rule which rule fired: {@code nyquist}, {@code mostly_stale}, {@code exec_near_period},
 *     {@code reaction} or {@code released_together}
 * @param periodMs the task's period in the run, ms
 * @param suggestedPeriodMs the period the advice suggests, ms
 * @param evidence the numbers the advice rests on, by snake_case name with a unit suffix
 * @param message one sentence a person reads: what to change and why
 */
public record AdviceItem(String task, String rule, double periodMs, double suggestedPeriodMs,
                         Map<String, Object> evidence, String message) {

    /**
     * Copies the evidence so the item stays immutable.
     *
     * @param task the task the advice is for
     * @param rule which rule fired: {@code nyquist}, {@code mostly_stale}, {@code exec_near_period}, {@code
     *     reaction} or {@code released_together}
     * @param periodMs the task's period in the run, ms
     * @param suggestedPeriodMs the period the advice suggests, ms
     * @param evidence the numbers the advice rests on, by snake_case name with a unit suffix
     * @param message one sentence a person reads: what to change and why
     */
    public AdviceItem {
        evidence = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(evidence));
    }
}
