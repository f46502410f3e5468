package io.rtaware.app.experiment;

import io.rtaware.app.UserError;
import io.rtaware.experiment.ExperimentPlan;
import io.rtaware.experiment.PlanFile;
import io.rtaware.experiment.RunConditions;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;
import java.util.function.Supplier;
import picocli.CommandLine.ParseResult;

/**
 * The plan of {@code experiment --resume --out DIR}: the one stored in DIR ({@link PlanFile}).
 * Options left out take the folder's values; {@code --runs} may raise the runs per set (the
 * experiment grows) but never lower them (the folder's results of the runs beyond would be left
 * outside its own plan); any other option given must agree with the folder, or the command is
 * refused with one line naming the option, its value and the folder's.
 */
final class ResumedPlan {

    private ResumedPlan() {
    }

    /**
     * @param dir the experiment folder
     * @param given what the user typed (which options were given)
     * @param requested the plan the options describe (defaults for those not given)
     * @return the plan to continue
     * @throws IOException if the folder's files cannot be read
     * @throws UserError if a given option contradicts the folder
     */
    static ExperimentPlan of(Path dir, ParseResult given, Supplier<ExperimentPlan> requested) throws IOException {
        ExperimentPlan stored = PlanFile.fromFolder(dir);
        boolean anyGiven = given.hasMatchedOption("--sets") || given.hasMatchedOption("--scenario")
                || given.hasMatchedOption("--time-scale") || given.hasMatchedOption("--seed")
                || given.hasMatchedOption("--robot-seed") || given.hasMatchedOption("--robots") || given.hasMatchedOption("--design")
                || given.hasMatchedOption("--cpu-limit")
                || given.hasMatchedOption("--grid-resolution") || given.hasMatchedOption("--runs")
                || given.hasMatchedOption("--shard");
        if (!anyGiven) {
            return stored;
        }
        ExperimentPlan asked = requested.get();
        RunConditions s = stored.conditions();
        RunConditions a = asked.conditions();
        check(given, "--sets", stored.sets().equals(asked.sets()), describeSets(asked), describeSets(stored), dir);
        check(given, "--scenario", s.scenario().equals(a.scenario()), a.scenario(), s.scenario(), dir);
        check(given, "--time-scale", s.timeScale() == a.timeScale(), a.timeScale(), s.timeScale(), dir);
        check(given, "--seed", s.seed() == a.seed(), a.seed(), s.seed(), dir);
        check(given, "--robot-seed", s.robotSeed() == a.robotSeed(), a.robotSeed(), s.robotSeed(), dir);
        check(given, "--robots", s.robots() == a.robots(), a.robots(), s.robots(), dir);
        check(given, "--design", s.design() == a.design(), a.design().label(), s.design().label(), dir);
        check(given, "--cpu-limit", Objects.equals(s.cpuLimitCpus(), a.cpuLimitCpus()), a.cpuLimitCpus(), s.cpuLimitCpus(), dir);
        check(given, "--grid-resolution", Objects.equals(s.gridResolutionM(), a.gridResolutionM()),
                a.gridResolutionM(), s.gridResolutionM() == null ? "run's default" : s.gridResolutionM(), dir);
        check(given, "--shard", stored.shard().equals(asked.shard()), asked.shard(), stored.shard(), dir);
        if (given.hasMatchedOption("--runs") && asked.runsPerSet() < stored.runsPerSet()) {
            throw new UserError("--resume never lowers the plan of " + dir + ": --runs " + asked.runsPerSet()
                    + " is fewer than its " + stored.runsPerSet() + " runs per set (leave --runs out, or use another --out)");
        }
        int runs = given.hasMatchedOption("--runs") ? asked.runsPerSet() : stored.runsPerSet();
        return new ExperimentPlan(stored.sets(), runs, s, stored.shard());
    }

    private static void check(ParseResult given, String option, boolean same, Object value, Object folderValue, Path dir) {
        if (given.hasMatchedOption(option) && !same) {
            throw new UserError("--resume continues the experiment in " + dir + " with its own plan: " + option + " "
                    + value + " differs from its " + folderValue + " (leave the option out, or use another --out)");
        }
    }

    private static String describeSets(ExperimentPlan plan) {
        return plan.sets().size() + " set(s) " + String.join(" ", plan.sets().stream().map(p -> p.shortLabel()).toList());
    }
}
