package io.rtaware.experiment;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * The runs of an experiment, the share of them this process makes, and the {@code rtaware run}
 * arguments of each.
 *
 * @param sets the sets compared, in order (set numbers count from 1 in this order)
 * @param runsPerSet runs of each set
 * @param conditions what all runs share
 * @param shard the share of the runs this process makes ({@link Shard#WHOLE} for all)
 */
public record ExperimentPlan(List<PeriodSet> sets, int runsPerSet, RunConditions conditions, Shard shard) {

    /**
     * The whole plan.
     *
     * @param sets the sets compared, in order
     * @param runsPerSet runs of each set
     * @param conditions what all runs share
     */
    public ExperimentPlan(List<PeriodSet> sets, int runsPerSet, RunConditions conditions) {
        this(sets, runsPerSet, conditions, Shard.WHOLE);
    }

    /**
     * Validates the fields.
     *
     * @param sets the sets compared, in order
     * @param runsPerSet runs of each set
     * @param conditions what all runs share
     * @param shard the share of the runs this process makes ({@link Shard#WHOLE} for all)
     */
    public ExperimentPlan {
        Objects.requireNonNull(shard, "shard");
        sets = List.copyOf(sets);
        if (sets.isEmpty()) {
            throw new IllegalArgumentException("an experiment needs at least one set");
        }
        if (runsPerSet < 1 || runsPerSet > MAX_RUNS_PER_SET) {
            throw new IllegalArgumentException("runs per set must be in 1.." + MAX_RUNS_PER_SET + ", got " + runsPerSet);
        }
        Objects.requireNonNull(conditions, "conditions");
    }

    /**
     * Most runs per set a plan may hold: 10 000 runs of the paper's course take months even at
     * the top time scale, while the plan lists every run in memory and in plan.json.
     */
    public static final int MAX_RUNS_PER_SET = 10_000;

    /**
     * @return the runs of this plan's shard, in the order of {@link #fullOrder()}
     */
    public List<PlannedRun> order() {
        return fullOrder().stream().filter(p -> shard.includes(p.set(), p.run())).toList();
    }

    /**
     * @return every run of the plan, whatever the shard, interleaved across sets (set 1 run 1,
     *     set 2 run 1, ..., set 1 run 2, ...) so that slow drift of the machine does not bias one set
     */
    public List<PlannedRun> fullOrder() {
        List<PlannedRun> order = new ArrayList<>();
        for (int run = 1; run <= runsPerSet; run++) {
            for (int set = 1; set <= sets.size(); set++) {
                order.add(new PlannedRun(set, run, sets.get(set - 1)));
            }
        }
        return order;
    }

    /**
     * @param planned a run of this plan
     * @param runDir the run's output folder
     * @return the arguments after {@code rtaware run}
     */
    public List<String> runArguments(PlannedRun planned, Path runDir) {
        List<String> args = new ArrayList<>(List.of(
                "--scenario", conditions.scenario(),
                "--periods", planned.periods().periodsArgument(),
                "--time-scale", Decimals.plain(conditions.timeScale()),
                "--seed", Long.toString(conditions.seedOf(planned.set(), planned.run())),
                "--robot-seed", Long.toString(conditions.robotSeedOf(planned.set(), planned.run()))));
        if (planned.periods().topSpeedMps() != null) {
            args.add("--top-speed");
            args.add(Decimals.plain(planned.periods().topSpeedMps()));
        }
        if (conditions.gridResolutionM() != null) {
            args.add("--grid-resolution");
            args.add(Decimals.plain(conditions.gridResolutionM()));
        }
        if (conditions.cpuLimitCpus() != null) {
            args.add("--cpu-limit");
            args.add(Decimals.plain(conditions.cpuLimitCpus()));
        }
        args.addAll(List.of("--out", runDir.toString(), "--quiet"));
        return args;
    }
}
