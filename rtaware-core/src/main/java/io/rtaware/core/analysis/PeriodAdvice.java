package io.rtaware.core.analysis;

import java.util.List;

/**
 * The advice for one periodic task: the interval of periods every rule allows, the bounds that
 * make it (each named with its figure), the period chosen in it and the verdict. Serialized in
 * snake_case as an item of the report's {@code advice} section. Immutable.
 *
 * @param task the task
 * @param periodMs its period in the run, ms
 * @param suggestedPeriodMs the period the advice suggests, ms (the run's when the verdict is
 *     {@value #KEEP}, {@value #MACHINE} or {@value #WITHDRAWN}); never below the lower bound
 * @param verdict {@value #KEEP}, {@value #SHORTEN}, {@value #LENGTHEN}, {@value #INFEASIBLE}
 *     (no period satisfies every bound), {@value #MACHINE} (the change rests on execution times a
 *     busy machine inflated) or {@value #WITHDRAWN} (a replay showed the change to be worse)
 * @param lowerMs the largest lower bound, ms
 * @param upperMs the smallest upper bound, ms, or null when no rule bounds the period from above
 * @param lowerBound the label of the bound that sets {@code lowerMs}
 * @param upperBound the label of the bound that sets {@code upperMs}, or null
 * @param bounds every bound, lower ones first
 * @param resolve where the interval is empty, what would open it (less work, another input
 *     rate, another core, ...); empty otherwise
 * @param notes what the advice says beside the period
 * @param message one sentence a person reads: the period, why, and what to change
 */
public record PeriodAdvice(String task, double periodMs, double suggestedPeriodMs, String verdict, double lowerMs,
                           Double upperMs, String lowerBound, String upperBound, List<PeriodBound> bounds,
                           List<String> resolve, List<AdviceNote> notes, String message) {

    /** The period lies in the interval and stays. */
    public static final String KEEP = "keep";
    /** The period is above an upper bound: the suggestion is shorter. */
    public static final String SHORTEN = "shorten";
    /** The period is below a lower bound, leaves the work no headroom or wakes the task mostly to no new data. */
    public static final String LENGTHEN = "lengthen";
    /** No period satisfies every bound: the suggestion is the least the task needs. */
    public static final String INFEASIBLE = "infeasible";
    /** The change rests on execution times that a busy or disturbed machine inflated: the period stays. */
    public static final String MACHINE = "machine";
    /** A what-if replay showed the suggested period to be worse: the period stays. */
    public static final String WITHDRAWN = "withdrawn";

    /**
     * Copies the lists so the advice stays immutable.
     *
     * @param task the task
     * @param periodMs its period in the run, ms
     * @param suggestedPeriodMs the suggested period, ms
     * @param verdict the verdict
     * @param lowerMs the largest lower bound, ms
     * @param upperMs the smallest upper bound, ms, or null
     * @param lowerBound the label of the largest lower bound
     * @param upperBound the label of the smallest upper bound, or null
     * @param bounds every bound
     * @param resolve what would open an empty interval
     * @param notes notes beside the period
     * @param message one sentence a person reads
     */
    public PeriodAdvice {
        bounds = List.copyOf(bounds);
        resolve = List.copyOf(resolve);
        notes = List.copyOf(notes);
    }

    /** @return true if the suggestion differs from the run's period */
    public boolean changesPeriod() {
        return suggestedPeriodMs != periodMs;
    }

    /**
     * @param reason why, with the figures that show it
     * @return this advice withdrawn: the period stays, the message says why
     */
    public PeriodAdvice withdrawn(String reason) {
        return new PeriodAdvice(task, periodMs, periodMs, WITHDRAWN, lowerMs, upperMs, lowerBound, upperBound, bounds,
                resolve, notes, "'" + task + "' keeps " + Num.ms(periodMs) + ": the suggested "
                + Num.ms(suggestedPeriodMs) + " is withdrawn, " + reason + " (it was: " + message + ")");
    }
}
