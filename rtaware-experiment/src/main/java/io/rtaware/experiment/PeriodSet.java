package io.rtaware.experiment;

import io.rtaware.nav.Behavior;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.stream.Collectors;

/**
 * One experiment set: a name and the period of each of the four behaviors, in ms (period and
 * deadline, as in Table I of the paper).
 *
 * @param name the set's label, e.g. {@code Set 1}
 * @param periodsMs period per task, keyed by the names in {@link #TASKS}, in that order
 */
public record PeriodSet(String name, Map<String, Long> periodsMs) {

    /** The behaviors whose periods an experiment varies, in the paper's column order. */
    public static final List<String> TASKS = Behavior.taskNames();

    /**
     * @param name the set's label
     * @param periodsMs a period in ms for exactly the tasks in {@link #TASKS}
     */
    public PeriodSet {
        Objects.requireNonNull(name, "name");
        if (!periodsMs.keySet().equals(new java.util.HashSet<>(TASKS))) {
            throw new IllegalArgumentException("periods must be given for exactly " + TASKS + ", got " + periodsMs.keySet());
        }
        Map<String, Long> ordered = new LinkedHashMap<>();
        for (String task : TASKS) {
            long p = periodsMs.get(task);
            if (p <= 0) {
                throw new IllegalArgumentException("period of " + task + " must be positive, got " + p);
            }
            ordered.put(task, p);
        }
        periodsMs = Collections.unmodifiableMap(ordered);
    }

    /**
     * @param name the set's label
     * @param waypointMs period of {@code waypoint}
     * @param obstacleMs period of {@code obstacle}
     * @param occupancyMs period of {@code occupancy}
     * @param plannerMs period of {@code planner}
     * @return the set
     */
    public static PeriodSet of(String name, long waypointMs, long obstacleMs, long occupancyMs, long plannerMs) {
        return new PeriodSet(name, Map.of("waypoint", waypointMs, "obstacle", obstacleMs,
                "occupancy", occupancyMs, "planner", plannerMs));
    }

    /** @return the value of {@code rtaware run --periods}, e.g. {@code waypoint=100,obstacle=50,...} */
    public String periodsArgument() {
        return periodsMs.entrySet().stream().map(e -> e.getKey() + "=" + e.getValue()).collect(Collectors.joining(","));
    }

    /** @return the periods as {@code 100/50/100/100} in the order of {@link #TASKS} */
    public String shortLabel() {
        return periodsMs.values().stream().map(String::valueOf).collect(Collectors.joining("/"));
    }
}
