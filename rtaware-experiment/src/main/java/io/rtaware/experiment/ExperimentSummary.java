package io.rtaware.experiment;

import com.fasterxml.jackson.annotation.JsonIgnore;
import com.fasterxml.jackson.annotation.JsonProperty;
import io.rtaware.experiment.claims.Claim;
import io.rtaware.experiment.claims.NotEvaluated;
import io.rtaware.experiment.claims.PaperClaims;
import io.rtaware.experiment.claims.RuleVerdict;
import io.rtaware.experiment.stats.RateInterval;
import io.rtaware.experiment.stats.SampleStats;
import io.rtaware.experiment.stats.WelchTest;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Everything the report says, as written to {@code summary.json}: the profile, per set the
 * rows of Tables I and II and the missed deadlines, Welch t-tests between every pair of sets,
 * and the paper's published numbers. Computed from {@code results.csv} rows alone, so the
 * experiment and {@code rtaware report} give the same numbers.
 *
 * <p>Which runs count: run time statistics are over the runs that completed the course (the
 * time to finish is only defined for them, as in the paper's Table I); distance statistics and
 * missed deadlines are over every run that ended on the course (completed, timeout, stuck);
 * {@code error} rows count in {@code runs} and {@code outcomes} only.
 *
 * @param schema always {@link #SCHEMA}
 * @param profile the conditions of the runs
 * @param sets per set, in set order
 * @param tTests Welch tests per quantity ({@code run_time_s}, {@code distance_to_finish_m})
 * @param paper the paper's published numbers (the paper's, not ours)
 * @param sweptTasks the tasks whose period differs between sets, in task order (see
 *     {@link SetSummary#sweptPeriodMs()})
 * @param claims the paper's claims with a verdict computed from these results ({@link PaperClaims})
 * @param claimsNotEvaluated the paper's claims these results cannot decide, with the reason
 * @param rules rtaware's own rules (not the paper's) checked by these results, or not evaluated with
 *     the reason ({@link RuleVerdict})
 * @param conditions the machine during the runs: how many were quiet, busy or disturbed, which are used, and the spread
 */
public record ExperimentSummary(String schema, ExperimentProfile profile, List<SetSummary> sets,
                                Map<String, List<PairTest>> tTests, PaperReference.Published paper,
                                List<String> sweptTasks, List<Claim> claims,
                                List<NotEvaluated> claimsNotEvaluated, List<RuleVerdict> rules,
                                ExperimentConditions conditions) {

    /** The schema identifier of {@code summary.json}. */
    public static final String SCHEMA = "rtaware.experiment/1";
    /** Name of the pooled entry of the four tasks in {@link SetSummary#misses()}. */
    public static final String ALL_TASKS = "all";
    /** The quantity keys of {@link #tTests()}. */
    public static final List<String> TESTED = List.of("run_time_s", "distance_to_finish_m");

    /**
     * One set's results.
     *
     * @param set the set's number
     * @param name the set's name
     * @param periodsMs the periods
     * @param runs rows in results.csv for this set
     * @param completed runs that completed the course ("trials completed")
     * @param outcomes runs per outcome
     * @param runTimeS run time over completed runs (Table I)
     * @param distanceToFinishM distance to the finish over measured runs (Table II)
     * @param distanceTravelledM path length over measured runs
     * @param collisions collisions summed over measured runs
     * @param misses per task and {@link #ALL_TASKS}, pooled over measured runs
     * @param topSpeedMps the set's top speed, or null for {@code run}'s default
     * @param measuredRuns runs that ended on the course (completed, timeout, stuck)
     * @param runsWithCollisions measured runs with at least one collision
     * @param sweptPeriodMs the period the swept tasks share in this set, or null when the sets do
     *     not differ in periods or this set's swept tasks have different periods (such a set is not
     *     on the period axis of the figures and claims)
     * @param mediatorCycles cycles the position mediator gave each winner, summed over the measured
     *     runs that report them; empty when none does
     * @param minClearanceM the smallest clearance of the robot's body in each measured run that
     *     reports it, metres
     * @param nearMisses near misses summed over the measured runs that report them, or null when none does
     * @param runsWithNearMisses measured runs with at least one near miss
     */
    public record SetSummary(int set, String name, Map<String, Long> periodsMs, int runs, int completed,
                             Map<String, Integer> outcomes, SampleStats runTimeS, SampleStats distanceToFinishM,
                             SampleStats distanceTravelledM, long collisions, Map<String, Misses> misses,
                             Double topSpeedMps, int measuredRuns, int runsWithCollisions, Long sweptPeriodMs,
                             Map<String, Long> mediatorCycles, SampleStats minClearanceM, Long nearMisses,
                             int runsWithNearMisses) {

        /**
         * @return the paper's set with this set's periods at this set's top speed (none given: the
         *     paper's), or null when the paper has no such set
         */
        @JsonIgnore
        public PaperReference.PaperSet paperSet() {
            return PaperReference.matching(new PeriodSet(name, periodsMs, topSpeedMps));
        }

        /** @return the share of measured runs with a near miss, 0 to 1, or null with no measured run */
        @JsonProperty("near_miss_rate")
        public Double nearMissRate() {
            return measuredRuns == 0 ? null : (double) runsWithNearMisses / measuredRuns;
        }

        /** @return the share of runs that completed the course, 0 to 1, or null with no runs */
        @JsonProperty("completion_rate")
        public Double completionRate() {
            return runs == 0 ? null : (double) completed / runs;
        }

        /**
         * The completion rate with its Wilson 95 % interval: an outcome of its own, since the runs
         * that did not finish (stuck, timeout, error) have no run time and Table I cannot show them.
         *
         * @return completed runs of all runs with the interval, or null with no runs
         */
        public RateInterval completions95() {
            return runs == 0 ? null : RateInterval.of(completed, runs);
        }

        /** @return {@link #completions95()}'s interval as {@code [lower, upper]}, 0 to 1, or null */
        @JsonProperty("completion_rate_ci95")
        public List<Double> completionRateCi95() {
            RateInterval r = completions95();
            return r == null ? null : List.of(r.lower(), r.upper());
        }

        /** @return the share of measured runs with a collision, 0 to 1, or null with no measured run */
        @JsonProperty("collision_rate")
        public Double collisionRate() {
            return measuredRuns == 0 ? null : (double) runsWithCollisions / measuredRuns;
        }

        /** @return the collision rate with its Wilson 95 % interval, or null with no measured run */
        public RateInterval collisions95() {
            return measuredRuns == 0 ? null : RateInterval.of(runsWithCollisions, measuredRuns);
        }

        /** @return the near-miss rate with its Wilson 95 % interval, or null with no measured run */
        public RateInterval nearMisses95() {
            return measuredRuns == 0 ? null : RateInterval.of(runsWithNearMisses, measuredRuns);
        }

        /** @return {@link #collisions95()}'s interval as {@code [lower, upper]}, 0 to 1, or null */
        @JsonProperty("collision_rate_ci95")
        public List<Double> collisionRateCi95() {
            RateInterval r = collisions95();
            return r == null ? null : List.of(r.lower(), r.upper());
        }

        /** @return {@link #nearMisses95()}'s interval as {@code [lower, upper]}, 0 to 1, or null */
        @JsonProperty("near_miss_rate_ci95")
        public List<Double> nearMissRateCi95() {
            RateInterval r = nearMisses95();
            return r == null ? null : List.of(r.lower(), r.upper());
        }
    }

    /**
     * Missed deadlines pooled over runs: {@code missPct = 100 * misses / releases}.
     *
     * @param releases releases summed over runs
     * @param misses misses summed over runs
     * @param missPct pooled percentage, or null with no releases
     * @param staleRuns stale runs summed over runs
     * @param execP99UsMean mean over runs of the per-run p99 execution time, µs (null for {@link #ALL_TASKS})
     * @param skipped releases skipped because the task was still running, summed over the runs
     *     that report them (they are misses too), or null when none does
     * @param maxSafePeriodMsMean mean over runs of the largest safe period the run's advice gave
     *     the task by the reaction rule, or null when no run gives one (and for {@link #ALL_TASKS})
     */
    public record Misses(long releases, long misses, Double missPct, long staleRuns, Double execP99UsMean, Long skipped,
                         Double maxSafePeriodMsMean) {
    }

    /**
     * A Welch test between two sets.
     *
     * @param setA the first set's number
     * @param setB the second set's number
     * @param test the result (t is mean of A minus mean of B over its standard error)
     */
    public record PairTest(int setA, int setB, WelchTest test) {
    }

    /**
     * @param rows every row of results.csv (at least one)
     * @param profile the conditions (see {@link ExperimentProfile#fromResults})
     * @return the summary
     */
    public static ExperimentSummary of(List<RunResult> rows, ExperimentProfile profile) {
        return of(rows, profile, ExperimentConditions.of(rows, true));
    }

    /**
     * @param rows the runs to summarize (the quiet ones, unless busy runs are included)
     * @param profile the experiment's profile
     * @param conditions the machine over all runs, and which are used
     * @return the summary of those runs, its claims judged on them alone
     */
    public static ExperimentSummary of(List<RunResult> rows, ExperimentProfile profile, ExperimentConditions conditions) {
        return of(rows, rows, profile, conditions);
    }

    /**
     * @param rows the runs to summarize (the quiet ones, unless busy runs are included)
     * @param all every run of the experiment, on which each claim is judged again
     *     ({@link Claim#verdictAllRuns()}, {@link Claim#fragile()})
     * @param profile the experiment's profile
     * @param conditions the machine over all runs, and which are used
     * @return the summary of those runs
     */
    public static ExperimentSummary of(List<RunResult> rows, List<RunResult> all, ExperimentProfile profile,
                                       ExperimentConditions conditions) {
        List<String> swept = sweptTasks(bySet(rows).values().stream().map(r -> r.get(0).periods()).toList());
        PaperClaims.Results used = results(rows, swept);
        PaperClaims.Verdicts verdicts = PaperClaims.evaluate(used, all.equals(rows) ? used : results(all, swept),
                profile.scenario());
        return new ExperimentSummary(SCHEMA, profile, used.sets(), used.tests(), PaperReference.published(), swept,
                verdicts.claims(), verdicts.notEvaluated(), verdicts.rules(), conditions);
    }

    private static Map<Integer, List<RunResult>> bySet(List<RunResult> rows) {
        Map<Integer, List<RunResult>> bySet = new TreeMap<>();
        rows.forEach(r -> bySet.computeIfAbsent(r.set(), k -> new ArrayList<>()).add(r));
        return bySet;
    }

    /** @return the sets of these runs summarized, with the Welch tests between every pair */
    private static PaperClaims.Results results(List<RunResult> rows, List<String> swept) {
        Map<Integer, List<RunResult>> bySet = bySet(rows);
        List<SetSummary> sets = new ArrayList<>();
        bySet.forEach((set, runs) -> sets.add(summarize(set, runs, sweptPeriod(runs.get(0).periods(), swept))));
        Map<String, List<PairTest>> tests = new LinkedHashMap<>();
        List<Integer> numbers = new ArrayList<>(bySet.keySet());
        for (String quantity : TESTED) {
            List<PairTest> pairs = new ArrayList<>();
            for (int i = 0; i < numbers.size(); i++) {
                for (int j = i + 1; j < numbers.size(); j++) {
                    List<RunResult> a = bySet.get(numbers.get(i));
                    List<RunResult> b = bySet.get(numbers.get(j));
                    pairs.add(new PairTest(numbers.get(i), numbers.get(j),
                            WelchTest.of(sample(a, quantity), sample(b, quantity))));
                }
            }
            tests.put(quantity, pairs);
        }
        return new PaperClaims.Results(sets, tests, rows);
    }

    /**
     * @param sets the sets of an experiment
     * @return the tasks whose period is not the same in every set, in task order
     */
    static List<String> sweptTasks(List<PeriodSet> sets) {
        return PeriodSet.TASKS.stream()
                .filter(t -> sets.stream().map(s -> s.periodsMs().get(t)).distinct().count() > 1).toList();
    }

    private static Long sweptPeriod(PeriodSet set, List<String> swept) {
        if (swept.isEmpty()) {
            return null;
        }
        List<Long> periods = swept.stream().map(t -> set.periodsMs().get(t)).distinct().toList();
        return periods.size() == 1 ? periods.get(0) : null;
    }

    /**
     * @param runs the rows of one set
     * @param quantity {@code run_time_s} (completed runs) or {@code distance_to_finish_m} (measured runs)
     * @return the sample the statistics, tests and figures use: values the runs did not give
     *     (NaN, non-finite) are left out
     */
    public static double[] sample(List<RunResult> runs, String quantity) {
        double[] all = switch (quantity) {
            case "run_time_s" -> runs.stream().filter(RunResult::completed).mapToDouble(RunResult::runTimeS).toArray();
            case "distance_to_finish_m" -> runs.stream().filter(RunResult::measured).mapToDouble(RunResult::distanceToFinishM).toArray();
            case "distance_travelled_m" -> runs.stream().filter(RunResult::measured).mapToDouble(RunResult::distanceTravelledM).toArray();
            default -> throw new IllegalArgumentException("unknown quantity " + quantity);
        };
        return java.util.Arrays.stream(all).filter(Double::isFinite).toArray();
    }

    private static SetSummary summarize(int set, List<RunResult> runs, Long sweptPeriodMs) {
        RunResult first = runs.get(0);
        Map<String, Integer> outcomes = new TreeMap<>();
        runs.forEach(r -> outcomes.merge(r.outcome(), 1, Integer::sum));
        List<RunResult> measured = runs.stream().filter(RunResult::measured).toList();
        Map<String, Misses> misses = new LinkedHashMap<>();
        long allReleases = 0;
        long allMisses = 0;
        long allStale = 0;
        for (String task : PeriodSet.TASKS) {
            List<TaskResult> t = measured.stream().map(r -> r.tasks().get(task)).filter(java.util.Objects::nonNull).toList();
            long releases = t.stream().mapToLong(TaskResult::releases).sum();
            long missed = t.stream().mapToLong(TaskResult::misses).sum();
            long stale = t.stream().mapToLong(TaskResult::staleRuns).sum();
            SampleStats p99 = SampleStats.of(t.stream().mapToDouble(TaskResult::execP99Us).toArray());
            Long skipped = sumOrNull(t.stream().map(TaskResult::skipped).toList());
            SampleStats safe = SampleStats.of(t.stream().map(TaskResult::maxSafePeriodMs).filter(java.util.Objects::nonNull)
                    .mapToDouble(Double::doubleValue).toArray());
            misses.put(task, new Misses(releases, missed, pct(missed, releases), stale, p99.mean(), skipped, safe.mean()));
            allReleases += releases;
            allMisses += missed;
            allStale += stale;
        }
        Long allSkipped = sumOrNull(misses.values().stream().map(Misses::skipped).toList());
        misses.put(ALL_TASKS, new Misses(allReleases, allMisses, pct(allMisses, allReleases), allStale, null, allSkipped,
                null));
        long collisions = measured.stream().map(RunResult::collisions).filter(java.util.Objects::nonNull)
                .mapToLong(Integer::longValue).sum();
        int withCollisions = (int) measured.stream().filter(r -> r.collisions() != null && r.collisions() > 0).count();
        Map<String, Long> mediator = new LinkedHashMap<>();
        for (String winner : RunResult.MEDIATOR_WINNERS) {
            Long cycles = sumOrNull(measured.stream().map(r -> r.mediatorCycles().get(winner)).toList());
            if (cycles != null) {
                mediator.put(winner, cycles);
            }
        }
        double[] clearances = measured.stream().map(RunResult::minClearanceM).filter(java.util.Objects::nonNull)
                .mapToDouble(Double::doubleValue).toArray();
        Long nearMisses = sumOrNull(measured.stream().map(RunResult::nearMisses).toList());
        int withNearMisses = (int) measured.stream().filter(r -> r.nearMisses() != null && r.nearMisses() > 0).count();
        return new SetSummary(set, first.periods().name(), first.periods().periodsMs(), runs.size(),
                (int) runs.stream().filter(RunResult::completed).count(), outcomes,
                SampleStats.of(sample(runs, "run_time_s")), SampleStats.of(sample(runs, "distance_to_finish_m")),
                SampleStats.of(sample(runs, "distance_travelled_m")), collisions, misses, first.periods().topSpeedMps(),
                measured.size(), withCollisions, sweptPeriodMs, mediator, SampleStats.of(clearances), nearMisses,
                withNearMisses);
    }

    private static Long sumOrNull(List<Long> values) {
        List<Long> known = values.stream().filter(java.util.Objects::nonNull).toList();
        return known.isEmpty() ? null : known.stream().mapToLong(Long::longValue).sum();
    }

    private static Double pct(long misses, long releases) {
        return releases == 0 ? null : 100.0 * misses / releases;
    }
}
