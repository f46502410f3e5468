package io.rtaware.experiment;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * One finished run of an experiment: one row of {@code results.csv}. Measures a run could not
 * give (a run that crashed) are {@code NaN} or null, and such a run takes no part in the
 * statistics ({@link #measured()}).
 *
 * @param set the set's number, from 1, in the order of the sets
 * @param run the run's number within its set, from 1
 * @param periods the set's name and periods
 * @param conditions what all runs share
 * @param outcome {@code completed}, {@code timeout}, {@code stuck}, {@code interrupted} or {@code error}
 * @param runTimeS world seconds from start to the end of the run
 * @param distanceToFinishM distance from the robot's final position to the finish, metres
 * @param distanceTravelledM length of the path driven, metres
 * @param collisions collisions with the world, or null if unknown
 * @param waypointsReached waypoints reached, or null if unknown
 * @param waypointsTotal waypoints in the course, or null if unknown
 * @param tasks per behavior of {@link PeriodSet#TASKS}; empty when the run gave no report
 * @param mediatorCycles cycles the position mediator gave to each of {@link #MEDIATOR_WINNERS};
 *     empty when unknown (a run report without them, or results that predate them)
 * @param minClearanceM the smallest distance between the robot's body and any obstacle in the run,
 *     metres, or null if unknown
 * @param nearMisses approaches within the near-miss margin that did not touch, or null if unknown
 * @param machine the machine during the run ({@link RunMachine#NOT_RECORDED} for results that predate it)
 * @param times when the run was made ({@link RunTimes#UNRECORDED} for results that predate them)
 */
public record RunResult(int set, int run, PeriodSet periods, RunConditions conditions, String outcome,
                        double runTimeS, double distanceToFinishM, double distanceTravelledM,
                        Integer collisions, Integer waypointsReached, Integer waypointsTotal,
                        Map<String, TaskResult> tasks, Map<String, Long> mediatorCycles, Double minClearanceM,
                        Long nearMisses, RunMachine machine, RunTimes times) {

    /**
     * A result without the times it was made.
     *
     * @param set the set's number
     * @param run the run's number
     * @param periods the set
     * @param conditions the shared conditions
     * @param outcome how the run ended
     * @param runTimeS run time, s
     * @param distanceToFinishM distance to the finish, m
     * @param distanceTravelledM path length, m
     * @param collisions collisions, or null
     * @param waypointsReached waypoints reached, or null
     * @param waypointsTotal waypoints in the course, or null
     * @param tasks per behavior
     * @param mediatorCycles cycles per mediator winner
     * @param minClearanceM the smallest clearance, m, or null
     * @param nearMisses near misses, or null
     * @param machine the machine during the run
     */
    public RunResult(int set, int run, PeriodSet periods, RunConditions conditions, String outcome,
                     double runTimeS, double distanceToFinishM, double distanceTravelledM,
                     Integer collisions, Integer waypointsReached, Integer waypointsTotal,
                     Map<String, TaskResult> tasks, Map<String, Long> mediatorCycles, Double minClearanceM,
                     Long nearMisses, RunMachine machine) {
        this(set, run, periods, conditions, outcome, runTimeS, distanceToFinishM, distanceTravelledM, collisions,
                waypointsReached, waypointsTotal, tasks, mediatorCycles, minClearanceM, nearMisses, machine,
                RunTimes.UNRECORDED);
    }

    /**
     * A result without clearance measures and without recorded machine conditions.
     *
     * @param set the set's number
     * @param run the run's number
     * @param periods the set
     * @param conditions the shared conditions
     * @param outcome how the run ended
     * @param runTimeS run time, s
     * @param distanceToFinishM distance to the finish, m
     * @param distanceTravelledM path length, m
     * @param collisions collisions, or null
     * @param waypointsReached waypoints reached, or null
     * @param waypointsTotal waypoints in the course, or null
     * @param tasks per behavior
     * @param mediatorCycles cycles per mediator winner
     */
    public RunResult(int set, int run, PeriodSet periods, RunConditions conditions, String outcome,
                     double runTimeS, double distanceToFinishM, double distanceTravelledM,
                     Integer collisions, Integer waypointsReached, Integer waypointsTotal,
                     Map<String, TaskResult> tasks, Map<String, Long> mediatorCycles) {
        this(set, run, periods, conditions, outcome, runTimeS, distanceToFinishM, distanceTravelledM, collisions,
                waypointsReached, waypointsTotal, tasks, mediatorCycles, null, null, RunMachine.NOT_RECORDED);
    }

    /**
     * A result without recorded machine conditions.
     *
     * @param set the set's number
     * @param run the run's number
     * @param periods the set
     * @param conditions the shared conditions
     * @param outcome how the run ended
     * @param runTimeS run time, s
     * @param distanceToFinishM distance to the finish, m
     * @param distanceTravelledM path length, m
     * @param collisions collisions, or null
     * @param waypointsReached waypoints reached, or null
     * @param waypointsTotal waypoints in the course, or null
     * @param tasks per behavior
     * @param mediatorCycles cycles per mediator winner
     * @param minClearanceM the smallest clearance, m, or null
     * @param nearMisses near misses, or null
     */
    public RunResult(int set, int run, PeriodSet periods, RunConditions conditions, String outcome,
                     double runTimeS, double distanceToFinishM, double distanceTravelledM,
                     Integer collisions, Integer waypointsReached, Integer waypointsTotal,
                     Map<String, TaskResult> tasks, Map<String, Long> mediatorCycles, Double minClearanceM,
                     Long nearMisses) {
        this(set, run, periods, conditions, outcome, runTimeS, distanceToFinishM, distanceTravelledM, collisions,
                waypointsReached, waypointsTotal, tasks, mediatorCycles, minClearanceM, nearMisses,
                RunMachine.NOT_RECORDED);
    }

    /**
     * A result without clearance measures.
     *
     * @param set the set's number
     * @param run the run's number
     * @param periods the set
     * @param conditions the shared conditions
     * @param outcome how the run ended
     * @param runTimeS run time, s
     * @param distanceToFinishM distance to the finish, m
     * @param distanceTravelledM path length, m
     * @param collisions collisions, or null
     * @param waypointsReached waypoints reached, or null
     * @param waypointsTotal waypoints in the course, or null
     * @param tasks per behavior
     * @param mediatorCycles cycles per mediator winner
     * @param machine the machine during the run
     */
    public RunResult(int set, int run, PeriodSet periods, RunConditions conditions, String outcome,
                     double runTimeS, double distanceToFinishM, double distanceTravelledM,
                     Integer collisions, Integer waypointsReached, Integer waypointsTotal,
                     Map<String, TaskResult> tasks, Map<String, Long> mediatorCycles, RunMachine machine) {
        this(set, run, periods, conditions, outcome, runTimeS, distanceToFinishM, distanceTravelledM, collisions,
                waypointsReached, waypointsTotal, tasks, mediatorCycles, null, null, machine);
    }

    /**
     * @param m the machine during the run
     * @return this result with it
     */
    public RunResult withMachine(RunMachine m) {
        return new RunResult(set, run, periods, conditions, outcome, runTimeS, distanceToFinishM, distanceTravelledM,
                collisions, waypointsReached, waypointsTotal, tasks, mediatorCycles, minClearanceM, nearMisses, m, times);
    }

    /**
     * @param t when the run was made
     * @return this result with those times
     */
    public RunResult withTimes(RunTimes t) {
        return new RunResult(set, run, periods, conditions, outcome, runTimeS, distanceToFinishM, distanceTravelledM,
                collisions, waypointsReached, waypointsTotal, tasks, mediatorCycles, minClearanceM, nearMisses, machine, t);
    }

    /** What the position mediator can choose in a cycle: the avoider's request, the waypoint planner's, or a stop. */
    public static final List<String> MEDIATOR_WINNERS = List.of("obstacle", "waypoint", "stop");

    /** Outcome of a run that reached the finish. */
    public static final String COMPLETED = "completed";
    /** Outcome recorded when the run's process failed or left no readable report. */
    public static final String ERROR = "error";
    /** Outcomes of runs that ended on the course and so measure the controller. */
    public static final Set<String> MEASURED_OUTCOMES = Set.of(COMPLETED, "timeout", "stuck");

    /**
     * Validates the fields.
     *
     * @param set the set's number, from 1, in the order of the sets
     * @param run the run's number within its set, from 1
     * @param periods the set's name and periods
     * @param conditions what all runs share
     * @param outcome {@code completed}, {@code timeout}, {@code stuck}, {@code interrupted} or {@code error}
     * @param runTimeS world seconds from start to the end of the run
     * @param distanceToFinishM distance from the robot's final position to the finish, metres
     * @param distanceTravelledM length of the path driven, metres
     * @param collisions collisions with the world, or null if unknown
     * @param waypointsReached waypoints reached, or null if unknown
     * @param waypointsTotal waypoints in the course, or null if unknown
     * @param tasks per behavior of {@link PeriodSet#TASKS}; empty when the run gave no report
     * @param mediatorCycles cycles the position mediator gave to each of {@link #MEDIATOR_WINNERS}; empty when
     *     unknown (a run report without them, or results that predate them)
     * @param minClearanceM the smallest clearance to any obstacle in the run, metres, or null if unknown
     * @param nearMisses approaches within the near-miss margin that did not touch, or null if unknown
     * @param machine the machine during the run
     * @param times when the run was made
     */
    public RunResult {
        Objects.requireNonNull(times, "times");
        Objects.requireNonNull(periods, "periods");
        Objects.requireNonNull(conditions, "conditions");
        Objects.requireNonNull(outcome, "outcome");
        Objects.requireNonNull(machine, "machine");
        tasks = Map.copyOf(tasks);
        mediatorCycles = Map.copyOf(mediatorCycles);
        if (set < 1 || run < 1) {
            throw new IllegalArgumentException("set and run count from 1, got set " + set + " run " + run);
        }
        String impossible = impossibleValue(runTimeS, distanceToFinishM, distanceTravelledM, collisions,
                waypointsReached, waypointsTotal, tasks, mediatorCycles);
        if (impossible != null) {
            throw new IllegalArgumentException(impossible);
        }
    }

    /**
     * The values no run can give (a measure a run could not give is NaN or null, never out of its
     * range): a negative time, distance or count, misses above releases, skipped releases above
     * misses, a miss percentage outside 0..100, more waypoints reached than the course has.
     *
     * @return the first such value, named, or null
     */
    private static String impossibleValue(double runTimeS, double distanceToFinishM, double distanceTravelledM,
                                          Integer collisions, Integer waypointsReached, Integer waypointsTotal,
                                          Map<String, TaskResult> tasks, Map<String, Long> mediatorCycles) {
        if (runTimeS < 0 || distanceToFinishM < 0 || distanceTravelledM < 0) {
            return "a negative run time or distance (" + runTimeS + " s, " + distanceToFinishM + " m, "
                    + distanceTravelledM + " m)";
        }
        if (collisions != null && collisions < 0 || waypointsReached != null && waypointsReached < 0
                || waypointsTotal != null && waypointsTotal < 0) {
            return "a negative count of collisions or waypoints";
        }
        if (waypointsReached != null && waypointsTotal != null && waypointsReached > waypointsTotal) {
            return waypointsReached + " waypoints reached of " + waypointsTotal;
        }
        for (Map.Entry<String, TaskResult> e : tasks.entrySet()) {
            TaskResult t = e.getValue();
            String task = "task '" + e.getKey() + "': ";
            if (t.releases() < 0 || t.misses() < 0 || t.staleRuns() < 0 || t.skipped() != null && t.skipped() < 0) {
                return task + "a negative count (releases " + t.releases() + ", misses " + t.misses() + ", stale runs "
                        + t.staleRuns() + ", skipped " + t.skipped() + ")";
            }
            if (t.misses() > t.releases()) {
                return task + t.misses() + " misses of " + t.releases() + " releases";
            }
            if (t.skipped() != null && t.skipped() > t.misses()) {
                return task + t.skipped() + " skipped releases of " + t.misses() + " misses (each skipped one is a miss)";
            }
            if (t.missPct() < 0 || t.missPct() > 100) {
                return task + "a miss rate of " + t.missPct() + " %";
            }
            if (t.execP99Us() < 0) {
                return task + "a negative execution time (" + t.execP99Us() + " us)";
            }
        }
        for (Map.Entry<String, Long> e : mediatorCycles.entrySet()) {
            if (e.getValue() == null || e.getValue() < 0) {
                return "mediator cycles won by '" + e.getKey() + "': " + e.getValue();
            }
        }
        return null;
    }

    /**
     * A result without mediator counts.
     *
     * @param set the set's number
     * @param run the run's number
     * @param periods the set
     * @param conditions the shared conditions
     * @param outcome how the run ended
     * @param runTimeS run time, s
     * @param distanceToFinishM distance to the finish, m
     * @param distanceTravelledM path length, m
     * @param collisions collisions, or null
     * @param waypointsReached waypoints reached, or null
     * @param waypointsTotal waypoints in the course, or null
     * @param tasks per behavior
     */
    public RunResult(int set, int run, PeriodSet periods, RunConditions conditions, String outcome,
                     double runTimeS, double distanceToFinishM, double distanceTravelledM,
                     Integer collisions, Integer waypointsReached, Integer waypointsTotal,
                     Map<String, TaskResult> tasks) {
        this(set, run, periods, conditions, outcome, runTimeS, distanceToFinishM, distanceTravelledM, collisions,
                waypointsReached, waypointsTotal, tasks, Map.of());
    }

    /**
     * @param set the set's number
     * @param run the run's number
     * @param periods the set
     * @param conditions the shared conditions
     * @return the row recorded for a run whose process failed
     */
    public static RunResult error(int set, int run, PeriodSet periods, RunConditions conditions) {
        return new RunResult(set, run, periods, conditions, ERROR, Double.NaN, Double.NaN, Double.NaN,
                null, null, null, Map.of());
    }

    /** @return the world seed this run was given ({@link RunConditions#seedOf(int, int)}) */
    public long worldSeed() {
        return conditions.seedOf(set, run);
    }

    /** @return the robot seed this run was given ({@link RunConditions#robotSeedOf(int, int)}) */
    public long robotSeed() {
        return conditions.robotSeedOf(set, run);
    }

    /** @return true if the run ended on the course (completed, timeout, stuck) */
    public boolean measured() {
        return MEASURED_OUTCOMES.contains(outcome);
    }

    /** @return true if the run reached the finish */
    public boolean completed() {
        return COMPLETED.equals(outcome);
    }
}
