package io.rtaware.core.analysis;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The period advice of a run: one {@link PeriodAdvice} per periodic task, and the check of the
 * suggested periods as one set. Immutable.
 *
 * @param cores the cores the tasks may use, for which the set was checked
 * @param tasks one item per periodic task, in report order
 * @param suggestedSet the schedulability of the suggested periods on {@code cores} cores
 */
public record Advice(int cores, List<PeriodAdvice> tasks, SchedulabilityReport suggestedSet) {

    /**
     * Copies the list so the advice stays immutable.
     *
     * @param cores the cores the tasks may use
     * @param tasks one item per periodic task
     * @param suggestedSet the schedulability of the suggested periods
     */
    public Advice {
        tasks = List.copyOf(tasks);
    }

    /** @return the suggested period of every task whose suggestion differs from its period, ms, in report order */
    public Map<String, Double> changedPeriodsMs() {
        Map<String, Double> periods = new LinkedHashMap<>();
        for (PeriodAdvice a : tasks) {
            if (a.changesPeriod()) {
                periods.put(a.task(), a.suggestedPeriodMs());
            }
        }
        return periods;
    }

    /**
     * @param task a task's name
     * @return its advice, or null if it has none (not periodic, or unknown)
     */
    public PeriodAdvice task(String task) {
        return tasks.stream().filter(a -> a.task().equals(task)).findFirst().orElse(null);
    }
}
