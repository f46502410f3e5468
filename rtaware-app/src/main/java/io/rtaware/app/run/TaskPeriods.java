package io.rtaware.app.run;

import io.rtaware.app.UserError;
import io.rtaware.core.time.Durations;
import io.rtaware.nav.Behavior;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The periods of the paper's four behaviors, as given by {@code --periods
 * waypoint=100ms,obstacle=50ms,occupancy=100ms,planner=100ms} (each period with its unit, as
 * {@link Durations#parseNanos} reads it). Tasks not named keep their default. Immutable.
 */
public final class TaskPeriods {

    /** The behaviors whose periods can be set, in the paper's order (Table I). */
    public static final List<String> TASKS = Behavior.taskNames();

    private final Map<String, Long> periodsNs;

    private TaskPeriods(Map<String, Long> periodsNs) {
        this.periodsNs = Collections.unmodifiableMap(periodsNs);
    }

    /** @return the paper's Set 4 (100/50/100/100 ms, each {@link Behavior}'s default), the default of {@code run} */
    public static TaskPeriods paperSet4() {
        return new TaskPeriods(Behavior.defaultPeriodsNs());
    }

    /**
     * @param waypointMs waypoint planner period in ms
     * @param obstacleMs obstacle avoider period in ms
     * @param occupancyMs occupancy grid period in ms
     * @param plannerMs path planner period in ms
     * @return the periods
     */
    public static TaskPeriods of(double waypointMs, double obstacleMs, double occupancyMs, double plannerMs) {
        Map<String, Long> m = new LinkedHashMap<>();
        m.put(Behavior.WAYPOINT.taskName(), Math.round(waypointMs * 1e6));
        m.put(Behavior.OBSTACLE.taskName(), Math.round(obstacleMs * 1e6));
        m.put(Behavior.OCCUPANCY.taskName(), Math.round(occupancyMs * 1e6));
        m.put(Behavior.PLANNER.taskName(), Math.round(plannerMs * 1e6));
        return new TaskPeriods(m);
    }

    /**
     * @param periodsNs period in ns of each task, in the controller's order
     * @return the periods (e.g. a recorded controller's, the defaults of {@code replay --periods})
     */
    public static TaskPeriods ofNanos(Map<String, Long> periodsNs) {
        return new TaskPeriods(new LinkedHashMap<>(periodsNs));
    }

    /**
     * Parses the {@code --periods} value over the defaults.
     *
     * @param text e.g. {@code waypoint=100ms,obstacle=50ms}
     * @param defaults periods of tasks the text does not name; the text may name only these tasks
     * @return the periods
     * @throws UserError naming the unknown task or the bad period
     */
    public static TaskPeriods parse(String text, TaskPeriods defaults) {
        Map<String, Long> m = new LinkedHashMap<>(defaults.periodsNs);
        if (text == null || text.isBlank()) {
            throw new UserError("--periods is empty; example: --periods waypoint=100ms,obstacle=50ms,occupancy=100ms,planner=100ms");
        }
        for (String entry : text.split(",")) {
            String[] kv = entry.split("=", 2);
            String task = kv[0].trim();
            if (kv.length != 2 || task.isEmpty()) {
                throw new UserError("--periods entry '" + entry.trim() + "' is not task=period (example: obstacle=50ms)");
            }
            if (!defaults.periodsNs.containsKey(task)) {
                throw new UserError("unknown task '" + task + "' in --periods; tasks: "
                        + String.join(", ", defaults.periodsNs.keySet()));
            }
            long ns;
            try {
                ns = Durations.parseNanos(kv[1].trim());
            } catch (IllegalArgumentException e) {
                throw new UserError("period of '" + task + "' in --periods: " + e.getMessage());
            }
            if (ns <= 0) {
                throw new UserError("period of '" + task + "' in --periods must be positive, got '" + kv[1].trim() + "'");
            }
            m.put(task, ns);
        }
        return new TaskPeriods(m);
    }

    /**
     * @param task one of {@link #TASKS}
     * @return its period in nanoseconds
     */
    public long periodNs(String task) {
        Long ns = periodsNs.get(task);
        if (ns == null) {
            throw new IllegalArgumentException("unknown task '" + task + "'; tasks: " + String.join(", ", TASKS));
        }
        return ns;
    }

    /** @return periods in ns by task, in the paper's order */
    public Map<String, Long> nanosByTask() {
        return periodsNs;
    }

    /** @return periods in ms by task, in the paper's order (the report's {@code periods_ms}) */
    public Map<String, Double> millis() {
        Map<String, Double> m = new LinkedHashMap<>();
        periodsNs.forEach((k, v) -> m.put(k, v / 1e6));
        return m;
    }

    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder();
        periodsNs.forEach((k, v) -> sb.append(sb.length() == 0 ? "" : ",").append(k).append('=').append(Durations.format(v)));
        return sb.toString();
    }
}
