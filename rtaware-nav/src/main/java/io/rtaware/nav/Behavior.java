package io.rtaware.nav;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The paper's four behaviors, in the order of its Table I: the tasks whose periods a user sets
 * on the command line ({@code run --periods}), an experiment varies and the live view shows.
 * Each carries its task name and its default period (the paper's Set 4: waypoint 100 ms,
 * obstacle 50 ms, occupancy 100 ms, planner 100 ms), written here once for every module.
 */
public enum Behavior {
    /** WAYPOINTPLANNER: moves the robot through the waypoints. */
    WAYPOINT("waypoint", 100_000_000L),
    /** LASEROBSTACLEAVOIDANCE: slows down and turns away from obstacles seen by the laser. */
    OBSTACLE("obstacle", 50_000_000L),
    /** OCCUPANCYGRIDMAPPING: keeps the occupancy grid from laser and position. */
    OCCUPANCY("occupancy", 100_000_000L),
    /** DIJKSTRAPATHPLANNER: keeps a path from the robot to the closest goal. */
    PLANNER("planner", 100_000_000L);

    private final String taskName;
    private final long defaultPeriodNs;

    Behavior(String taskName, long defaultPeriodNs) {
        this.taskName = taskName;
        this.defaultPeriodNs = defaultPeriodNs;
    }

    /** @return the task's name in the monitor and in reports */
    public String taskName() {
        return taskName;
    }

    /** @return the default period in ns (the paper's Set 4) */
    public long defaultPeriodNs() {
        return defaultPeriodNs;
    }

    /** @return the four task names in Table I order */
    public static List<String> taskNames() {
        return Arrays.stream(values()).map(Behavior::taskName).toList();
    }

    /** @return task name to default period in ns, in Table I order (a new map) */
    public static Map<String, Long> defaultPeriodsNs() {
        Map<String, Long> m = new LinkedHashMap<>();
        for (Behavior b : values()) {
            m.put(b.taskName, b.defaultPeriodNs);
        }
        return m;
    }

    /**
     * @param taskName a task name
     * @return the behavior of that name
     * @throws IllegalArgumentException for another name, listing the known ones
     */
    public static Behavior ofTaskName(String taskName) {
        for (Behavior b : values()) {
            if (b.taskName.equals(taskName)) {
                return b;
            }
        }
        throw new IllegalArgumentException("unknown behavior '" + taskName + "' (known: "
                + String.join(", ", taskNames()) + ")");
    }
}
