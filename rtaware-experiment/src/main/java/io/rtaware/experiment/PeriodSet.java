package io.rtaware.experiment;

import io.rtaware.nav.Behavior;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.stream.Collectors;

/**
 * One experiment set: a name, the period of each of the four behaviors, in ms (period and
 * deadline, as in Table I of the paper), and optionally the robot's top speed for the set's
 * runs (passed to {@code rtaware run} as {@code --top-speed}).
 *
 * @param name the set's label, e.g. {@code Set 1}
 * @param periodsMs period per task, keyed by the names in {@link #TASKS}, in that order
 * @param topSpeedMps the robot's top speed in m/s, or null for {@code run}'s default
 */
public record PeriodSet(String name, Map<String, Long> periodsMs, Double topSpeedMps) {

    /** The behaviors whose periods an experiment varies, in the paper's column order. */
    public static final List<String> TASKS = Behavior.taskNames();

    /**
     * @param name the set's label
     * @param periodsMs a period in ms for exactly the tasks in {@link #TASKS}
     * @param topSpeedMps a positive, finite speed in m/s, or null
     */
    public PeriodSet {
        Objects.requireNonNull(name, "name");
        if (topSpeedMps != null && !(topSpeedMps > 0 && Double.isFinite(topSpeedMps))) {
            throw new IllegalArgumentException("top speed must be a positive number of m/s, got " + topSpeedMps);
        }
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
     * A set at {@code run}'s default top speed.
     *
     * @param name the set's label
     * @param periodsMs a period in ms for exactly the tasks in {@link #TASKS}
     */
    public PeriodSet(String name, Map<String, Long> periodsMs) {
        this(name, periodsMs, null);
    }

    /**
     * @param speedMps the top speed, or null for {@code run}'s default
     * @return this set with that top speed
     */
    public PeriodSet withTopSpeed(Double speedMps) {
        return new PeriodSet(name, periodsMs, speedMps);
    }

    /**
     * @param other another set
     * @return true if both give the same periods and the same top speed (names may differ)
     */
    public boolean sameRunsAs(PeriodSet other) {
        return periodsMs.equals(other.periodsMs) && Objects.equals(topSpeedMps, other.topSpeedMps);
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

    /** @return the value of {@code rtaware run --periods}, e.g. {@code waypoint=100ms,obstacle=50ms,...} */
    public String periodsArgument() {
        return periodsMs.entrySet().stream().map(e -> e.getKey() + "=" + e.getValue() + "ms").collect(Collectors.joining(","));
    }

    /** @return the periods as {@code 100/50/100/100} in the order of {@link #TASKS} */
    public String shortLabel() {
        return periodsMs.values().stream().map(String::valueOf).collect(Collectors.joining("/"));
    }

    /** @return {@link #shortLabel()}, followed by {@code " at 0.3 m/s"} when the set has a top speed */
    public String label() {
        return topSpeedMps == null ? shortLabel() : shortLabel() + " at " + plainSpeed(topSpeedMps) + " m/s";
    }

    /**
     * @param speedMps a speed
     * @return it without trailing zeros, e.g. {@code 0.3}
     */
    public static String plainSpeed(double speedMps) {
        return Decimals.plain(speedMps);
    }
}
