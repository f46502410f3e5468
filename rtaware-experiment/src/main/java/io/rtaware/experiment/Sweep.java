package io.rtaware.experiment;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A sweep: sets that differ in the period of some tasks (all of them set to the same swept
 * value, the others at a base period) and/or in the robot's top speed. The sets are every
 * combination, speeds outermost: for each top speed, for each swept period, one set.
 *
 * @param tasks the tasks whose period is swept, in the order of {@link PeriodSet#TASKS}; with no
 *     swept periods, unused
 * @param periodsMs the swept periods, in ms, in the order given; empty for a speed-only sweep
 * @param basePeriodsMs the period of every task, in ms, where it is not swept
 * @param topSpeedsMps the top speeds, in m/s; empty for {@code run}'s default; more than one
 *     makes a speed sweep
 */
public record Sweep(List<String> tasks, List<Long> periodsMs, Map<String, Long> basePeriodsMs,
                    List<Double> topSpeedsMps) {

    /** The periods of the built-in sweeps, in ms: from below the paper's lock-up (5 ms) to eight laser scans. */
    public static final List<Long> PERIODS_MS = List.of(5L, 10L, 20L, 50L, 100L, 200L, 400L, 800L);

    /** The period of a task that is not swept, in ms: the laser's scan period, as the paper's Set 5. */
    public static final long BASE_PERIOD_MS = 100;

    /**
     * Validates and copies the fields.
     *
     * @param tasks the tasks whose period is swept, in the order of {@link PeriodSet#TASKS}; with no swept
     *     periods, unused
     * @param periodsMs the swept periods, in ms, in the order given; empty for a speed-only sweep
     * @param basePeriodsMs the period of every task, in ms, where it is not swept
     * @param topSpeedsMps the top speeds, in m/s; empty for {@code run}'s default; more than one makes a speed
     *     sweep
     */
    public Sweep {
        tasks = List.copyOf(tasks);
        periodsMs = List.copyOf(periodsMs);
        topSpeedsMps = List.copyOf(topSpeedsMps);
        basePeriodsMs = Map.copyOf(basePeriodsMs);
        if (!basePeriodsMs.keySet().containsAll(PeriodSet.TASKS)) {
            throw new IllegalArgumentException("base periods must be given for every task, got " + basePeriodsMs.keySet());
        }
        if (!periodsMs.isEmpty() && tasks.isEmpty()) {
            throw new IllegalArgumentException("a period sweep needs at least one task");
        }
        if (!PeriodSet.TASKS.containsAll(tasks)) {
            throw new IllegalArgumentException("unknown task in " + tasks);
        }
        if (periodsMs.isEmpty() && topSpeedsMps.size() < 2) {
            throw new IllegalArgumentException("a sweep needs periods or at least two top speeds");
        }
    }

    /**
     * @param tasks the swept tasks
     * @return the built-in sweep of those tasks over {@link #PERIODS_MS}, the others at
     *     {@link #BASE_PERIOD_MS}, at {@code run}'s default top speed
     */
    public static Sweep ofPeriods(List<String> tasks) {
        return new Sweep(tasks, PERIODS_MS, basePeriods(), List.of());
    }

    /** @return {@link #BASE_PERIOD_MS} for every task */
    public static Map<String, Long> basePeriods() {
        Map<String, Long> base = new LinkedHashMap<>();
        PeriodSet.TASKS.forEach(t -> base.put(t, BASE_PERIOD_MS));
        return base;
    }

    /** @return the sets, speeds outermost, each named after what it varies (e.g. {@code obstacle 50 ms at 0.3 m/s}) */
    public List<PeriodSet> sets() {
        List<Double> speeds = topSpeedsMps.isEmpty() ? java.util.Collections.singletonList(null) : topSpeedsMps;
        List<Long> periods = periodsMs.isEmpty() ? java.util.Collections.singletonList(null) : periodsMs;
        String group = tasks.size() == PeriodSet.TASKS.size() ? "all" : String.join("+", orderedTasks());
        List<PeriodSet> sets = new ArrayList<>();
        for (Double speed : speeds) {
            for (Long period : periods) {
                Map<String, Long> p = new LinkedHashMap<>();
                for (String task : PeriodSet.TASKS) {
                    p.put(task, period != null && tasks.contains(task) ? period : basePeriodsMs.get(task));
                }
                List<String> name = new ArrayList<>();
                if (period != null) {
                    name.add(group + " " + period + " ms");
                }
                if (speed != null && (topSpeedsMps.size() > 1 || period == null)) {
                    name.add((period == null ? "" : "at ") + PeriodSet.plainSpeed(speed) + " m/s");
                }
                sets.add(new PeriodSet(String.join(" ", name), p, speed));
            }
        }
        return List.copyOf(sets);
    }

    private List<String> orderedTasks() {
        return PeriodSet.TASKS.stream().filter(tasks::contains).toList();
    }
}
