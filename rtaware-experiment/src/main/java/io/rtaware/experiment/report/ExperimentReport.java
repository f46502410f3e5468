package io.rtaware.experiment.report;

import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.core.output.OutputFiles;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.experiment.Decimals;
import io.rtaware.experiment.ExperimentConditions;
import io.rtaware.experiment.ExperimentInputException;
import io.rtaware.experiment.ExperimentProfile;
import io.rtaware.experiment.ExperimentRunner;
import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ExperimentSummary.Misses;
import io.rtaware.experiment.ExperimentSummary.PairTest;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.PaperReference.PaperSet;
import io.rtaware.experiment.PeriodSet;
import io.rtaware.experiment.ResultsCsv;
import io.rtaware.experiment.RunConditions;
import io.rtaware.experiment.RunResult;
import io.rtaware.experiment.claims.Claim;
import io.rtaware.experiment.claims.PaperClaims;
import io.rtaware.experiment.stats.RateInterval;
import io.rtaware.experiment.stats.SampleStats;
import io.rtaware.experiment.stats.WelchTest;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * Renders an experiment folder's report from its {@code results.csv} (and the runs'
 * {@code trajectory.csv} files, and {@code experiment.json} for the machine when present):
 * {@code summary.json}, {@code report.md}, {@code report.html} and the figures.
 */
public final class ExperimentReport {

    /** The JSON summary's file name. */
    public static final String SUMMARY_FILE = "summary.json";
    /** The Markdown report's file name. */
    public static final String MARKDOWN_FILE = "report.md";
    /** The HTML report's file name (figures inline). */
    public static final String HTML_FILE = "report.html";

    private static final String NA = "n/a";

    private ExperimentReport() {
    }

    /**
     * @param dir an experiment folder with a {@code results.csv}
     * @param background the course drawn behind the paths
     * @return the summary written
     * @throws IOException if reading or writing fails
     * @throws ExperimentInputException if there is no results.csv with at least one row
     */
    public static ExperimentSummary render(Path dir, MapBackground background) throws IOException {
        return render(dir, background, false);
    }

    /**
     * @param dir an experiment folder with a {@code results.csv}
     * @param background the course drawn behind the paths
     * @param includeBusy true to use every run; false to use the quiet ones only
     *     ({@link ExperimentConditions#RULE})
     * @return the summary written
     * @throws IOException if reading or writing fails
     * @throws ExperimentInputException if there is no results.csv with at least one row, or no
     *     quiet run when only quiet runs are used
     */
    public static ExperimentSummary render(Path dir, MapBackground background, boolean includeBusy) throws IOException {
        return render(dir, background, includeBusy, false);
    }

    /**
     * @param dir an experiment folder with a {@code results.csv}
     * @param background the course drawn behind the paths
     * @param includeBusy true to use every run; false to use the quiet ones only
     *     ({@link ExperimentConditions#RULE})
     * @param allWhenNoneQuiet true to use every run, the report and summary labelled busy
     *     ({@link ExperimentConditions#busyLabel()}), when not one counts as quiet, instead of refusing
     *     the folder (experiment {@code --allow-busy}: those runs were asked for)
     * @return the summary written
     * @throws IOException if reading or writing fails
     * @throws ExperimentInputException if there is no results.csv with at least one row, or no
     *     quiet run when only quiet runs are used
     */
    public static ExperimentSummary render(Path dir, MapBackground background, boolean includeBusy,
                                           boolean allWhenNoneQuiet) throws IOException {
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        if (!Files.exists(csv)) {
            throw new ExperimentInputException(dir + " has no " + ResultsCsv.FILE_NAME + " (not an experiment folder?)");
        }
        List<RunResult> all = ResultsCsv.read(csv);
        if (all.isEmpty()) {
            throw new ExperimentInputException(csv + " has no runs yet: nothing to report");
        }
        boolean useAll = includeBusy || allWhenNoneQuiet && all.stream().noneMatch(ExperimentConditions::countsAsQuiet);
        ExperimentConditions conditions = ExperimentConditions.of(all, useAll);
        List<RunResult> rows = ExperimentConditions.used(all, useAll);
        if (rows.isEmpty()) {
            throw new ExperimentInputException(csv + ": none of its " + all.size() + " runs was made on a quiet machine ("
                    + conditions.machineCounts() + "); report them labelled with --include-busy, or re-run on a quiet "
                    + "machine");
        }
        // No disk cache: its clean-up registers a shutdown hook, which fails when the report is
        // written after Ctrl-C, during shutdown.
        javax.imageio.ImageIO.setUseCache(false);
        ExperimentProfile profile = ExperimentProfile.read(dir).orElse(ExperimentProfile.fromResults(rows));
        ExperimentSummary summary = ExperimentSummary.of(rows, all, profile, conditions);
        ObjectMapper mapper = ReportDocument.mapper();
        OutputFiles.write(dir.resolve(SUMMARY_FILE), OutputFiles.text(mapper.writeValueAsString(summary) + "\n"));

        Figures.taskMisses(summary, dir);
        Figures.setMisses(summary, dir);
        Map<String, double[]> runTimes = new LinkedHashMap<>();
        Map<String, double[]> distances = new LinkedHashMap<>();
        Map<Integer, List<RunResult>> bySet = new TreeMap<>();
        rows.forEach(r -> bySet.computeIfAbsent(r.set(), k -> new ArrayList<>()).add(r));
        for (SetSummary s : summary.sets()) {
            runTimes.put(s.name(), ExperimentSummary.sample(bySet.get(s.set()), "run_time_s"));
            distances.put(s.name(), ExperimentSummary.sample(bySet.get(s.set()), "distance_to_finish_m"));
        }
        Figures.boxPlot(runTimes, "Run time per set (completed runs)", "run time (s, world time)", dir, Figures.RUNTIME_BOX);
        Figures.boxPlot(distances, "Distance from the finish at the end of the run", "distance to finish (m)", dir,
                Figures.DISTANCE_BOX);
        Figures.trajectories(summary, trajectories(dir, rows), background, dir);
        SweepFigures.write(summary, dir);

        Blocks blocks = content(summary, rows.get(rows.size() - 1).conditions());
        OutputFiles.write(dir.resolve(MARKDOWN_FILE), OutputFiles.text(blocks.markdown()));
        OutputFiles.write(dir.resolve(HTML_FILE), OutputFiles.text(blocks.html("rtaware experiment report", dir)));
        return summary;
    }

    private static List<Trajectory> trajectories(Path dir, List<RunResult> rows) throws IOException {
        List<Trajectory> paths = new ArrayList<>();
        for (RunResult r : rows) {
            if (!r.measured()) {
                continue;
            }
            Path file = dir.resolve(ExperimentRunner.RUNS_DIR).resolve("set" + r.set() + "-run" + r.run())
                    .resolve(Trajectory.FILE_NAME);
            if (Files.exists(file)) {
                paths.add(Trajectory.read(file, r.set(), r.run()));
            }
        }
        return paths;
    }

    private static Blocks content(ExperimentSummary s, RunConditions robots) {
        Blocks b = new Blocks();
        ExperimentProfile p = s.profile();
        b.heading(1, "rtaware experiment report");
        if (s.conditions() != null && s.conditions().busyOnly()) {
            b.text("**Busy machine.** " + s.conditions().busyLabel());
        }
        String k = Decimals.plain(p.timeScale());
        b.text("Profile: scenario `" + p.scenario() + "`, time scale x" + k + " (world time runs " + k
                + " times faster than wall time, so each task's computation weighs " + k
                + " times more against its period), grid resolution "
                + (p.gridResolutionM() == null ? "`run`'s default" : Decimals.plain(p.gridResolutionM()) + " m")
                + ", seed " + p.seed() + " (set 1 run 1's), " + p.runsPerSet() + " run(s) per set planned"
                + (robots.cpuLimitCpus() == null ? "" : ", each run's JVM (controller and built-in server) under a CPU "
                        + "quota of " + Decimals.plain(robots.cpuLimitCpus()) + " CPUs (--cpu-limit; results.csv: cpu_limit_cpus)")
                + ".");
        b.text("Design: " + robots.robotsInWords() + "; the systematic odometry errors come from the robot seed, "
                + "each run's noise from its world seed (results.csv: seed, robot_seed, robots, design).");
        b.text("Machine: " + (p.machine() == null ? "not recorded (no experiment.json)" : p.machine())
                + ". The paper's runs: " + s.paper().source() + ".");
        if (s.conditions() != null) {
            b.text(s.conditions().text());
        }
        b.text("Which runs count: run time over the runs that completed the course; distance to the finish and missed "
                + "deadlines over every run that ended on the course (completed, timeout, stuck); `error` runs are only counted. "
                + "Missed deadlines are pooled: 100 x (misses summed over runs) / (releases summed over runs). "
                + "Columns marked **paper** are the paper's published numbers, not ours.");

        claims(b, s);

        completion(b, s);

        b.heading(2, "Table I: periods and run time");
        List<List<String>> rows = new ArrayList<>();
        for (SetSummary set : s.sets()) {
            PaperSet paper = set.paperSet();
            List<String> row = new ArrayList<>(List.of(set.name()));
            set.periodsMs().values().forEach(v -> row.add(Long.toString(v)));
            row.addAll(List.of(set.completed() + " of " + set.runs(), outcomes(set.outcomes()),
                    num(set.runTimeS().mean(), 2), num(set.runTimeS().sd(), 2),
                    paper == null ? "-" : num(paper.runTimeMeanS(), 2), paper == null ? "-" : num(paper.runTimeSdS(), 2)));
            rows.add(row);
        }
        b.table(List.of("set", "waypoint (ms)", "obstacle (ms)", "occupancy (ms)", "planner (ms)", "completed",
                "outcomes", "mean run time (s)", "SD (s)", "**paper** mean (s)", "**paper** SD (s)"), rows);

        b.heading(2, "Table II: distance from the finish position");
        rows = new ArrayList<>();
        for (SetSummary set : s.sets()) {
            PaperSet paper = set.paperSet();
            SampleStats d = set.distanceToFinishM();
            rows.add(List.of(set.name(), Integer.toString(d.n()), num(d.mean(), 2), num(d.sd(), 2), num(d.min(), 2),
                    num(d.max(), 2), paper == null ? "-" : num(paper.distanceMeanM(), 2),
                    paper == null ? "-" : num(paper.distanceSdM(), 2), paper == null ? "-" : num(paper.distanceMinM(), 2),
                    paper == null ? "-" : num(paper.distanceMaxM(), 2)));
        }
        b.table(List.of("set", "runs", "mean (m)", "SD (m)", "min (m)", "max (m)", "**paper** mean (m)",
                "**paper** SD (m)", "**paper** min (m)", "**paper** max (m)"), rows);

        b.heading(2, "Missed deadlines");
        rows = new ArrayList<>();
        for (SetSummary set : s.sets()) {
            List<String> row = new ArrayList<>(List.of(set.name()));
            for (String task : PeriodSet.TASKS) {
                row.add(missCell(set.misses().get(task)));
            }
            row.add(missCell(set.misses().get(ExperimentSummary.ALL_TASKS)));
            rows.add(row);
        }
        List<String> header = new ArrayList<>(List.of("set"));
        PeriodSet.TASKS.forEach(t -> header.add(t + " % (misses / releases)"));
        header.add("all four % (misses / releases)");
        b.table(header, rows);
        b.figure(Figures.FIG7 + ".png", "Missed deadlines per task per set (the paper's Fig. 7 shows the same measure)");
        b.figure(Figures.FIG8 + ".png", "Missed deadlines of all four tasks per set (the paper's Fig. 8)");

        rows = new ArrayList<>();
        for (SetSummary set : s.sets()) {
            List<String> row = new ArrayList<>(List.of(set.name()));
            for (String task : PeriodSet.TASKS) {
                Misses m = set.misses().get(task);
                row.add(m.staleRuns() + " / " + num(m.execP99UsMean(), 0));
            }
            rows.add(row);
        }
        List<String> h2 = new ArrayList<>(List.of("set"));
        PeriodSet.TASKS.forEach(t -> h2.add(t + ": stale runs / mean exec p99 (µs)"));
        b.table(h2, rows);

        robot(b, s);
        sweep(b, s);

        b.heading(2, "Welch t-tests between sets (two-sided)");
        b.text("t = (mean of A - mean of B) / standard error; df by Welch–Satterthwaite; p from Apache Commons Math; "
                + "confidence = 1 - p, as the paper quotes it. A p below 0.05 (confidence above 95%) is the usual threshold "
                + "for 'statistically different'. Detectable: the test's power as a size, the smallest difference of the "
                + "means it detects at alpha " + WelchTest.ALPHA + " with " + num(100 * WelchTest.POWER, 0) + "% power, "
                + "given the observed spreads and n; a 'no difference' is only as strong as that figure.");
        for (String quantity : ExperimentSummary.TESTED) {
            b.heading(3, "run_time_s".equals(quantity) ? "Run time (completed runs)" : "Distance to the finish");
            rows = new ArrayList<>();
            for (PairTest pair : s.tTests().get(quantity)) {
                WelchTest t = pair.test();
                rows.add(List.of(name(s, pair.setA()) + " vs " + name(s, pair.setB()), num(t.t(), 3), num(t.df(), 2),
                        num(t.p(), 4), t.confidence() == null ? NA : num(100 * t.confidence(), 1) + "%",
                        num(t.detectableDifference(), 3), t.applicable() ? "" : NA + ": " + t.note()));
            }
            b.table(List.of("sets", "t", "df", "p", "confidence 1 - p",
                    "detectable (" + ("run_time_s".equals(quantity) ? "s" : "m") + ")", "note"), rows);
            List<String> said = s.paper().tests().stream().filter(pt -> pt.quantity().equals(quantity))
                    .map(pt -> (pt.setA() == null ? "all pairs" : "Set " + pt.setA() + " vs Set " + pt.setB()) + ": "
                            + pt.statement()).toList();
            b.text("**paper** (Section VII): " + String.join("; ", said) + ".");
        }

        b.heading(2, "Run time, distance and paths");
        b.figure(Figures.RUNTIME_BOX + ".png", "Run time per set, completed runs (box: quartiles, whiskers: range within 1.5 IQR)");
        b.figure(Figures.DISTANCE_BOX + ".png", "Distance from the finish at the end of each run, per set");
        b.figure(Figures.TRAJECTORIES + ".png", "Every run's path, one colour per set");
        rows = new ArrayList<>();
        for (SetSummary set : s.sets()) {
            SampleStats d = set.distanceTravelledM();
            rows.add(List.of(set.name(), num(d.mean(), 2), num(d.sd(), 2), Long.toString(set.collisions())));
        }
        b.table(List.of("set", "mean distance travelled (m)", "SD (m)", "collisions (all runs)"), rows);
        return b;
    }

    private static void claims(Blocks b, ExperimentSummary s) {
        b.heading(2, "Claims of the paper");
        b.text("Each verdict (reproduced, not reproduced, mixed) is computed from the results below by the rule in its row, "
                + "never set by hand. Thresholds: too slow means a period above " + PaperClaims.SLOW_ABOVE_MS
                + " ms, too fast " + PaperClaims.FAST_AT_MOST_MS + " ms or less (the set's swept period); an effect holds for a "
                + "set when it shows in at least " + num(100 * PaperClaims.MAJORITY, 0) + "% of its runs; misses fall when "
                + "Spearman's rho of miss % against period is at most " + PaperClaims.FALLS_RHO + " (over at least "
                + PaperClaims.MIN_PERIODS + " periods); t-tests at p < " + PaperClaims.ALPHA + ", 'on the verge' at a "
                + "confidence of " + num(100 * PaperClaims.VERGE_MIN, 0) + "-" + num(100 * PaperClaims.VERGE_MAX, 0)
                + "%; 'almost identical' set means within " + num(100 * PaperClaims.SAME_RUN_TIME, 0) + "% (run time) and "
                + num(100 * PaperClaims.SAME_DISTANCE, 0) + "% (distance) of their mean. Table I/II claims use the sets "
                + "whose periods are a paper set's, at the paper's top speed.");
        List<List<String>> rows = new ArrayList<>();
        for (Claim c : s.claims()) {
            rows.add(List.of(c.claim(), verdictCell(c.verdict().json(), c.caveats()), words(c.verdictAllRuns()),
                    c.evidence(), c.rule()));
        }
        b.text("Each claim is judged on the runs this report uses and again on all runs, busy ones included: a verdict "
                + "that differs between the two is marked fragile (the choice of runs decides it), and one that rests on "
                + "fewer than " + PaperClaims.SMALL_SAMPLE_RUNS + " runs in some set says so.");
        if (rows.isEmpty()) {
            b.text("No claim can be decided from these sets (see below).");
        } else {
            b.table(List.of("claim", "verdict", "on all runs", "evidence", "rule"), rows);
        }
        if (!s.claimsNotEvaluated().isEmpty()) {
            b.text("Not evaluated (the data is not in this experiment):");
            b.table(List.of("claim", "why not", "on all runs"), s.claimsNotEvaluated().stream()
                    .map(n -> List.of(n.claim(), n.reason(), words(n.verdictAllRuns())
                            + (n.fragile() ? " (fragile)" : ""))).toList());
        }
        rules(b, s);
    }

    /** rtaware's own rules, apart from the paper's claims: none of them is the paper's. */
    private static void rules(Blocks b, ExperimentSummary s) {
        if (s.rules().isEmpty()) {
            return;
        }
        b.heading(2, "rtaware's own rules");
        b.text("These rules are rtaware's, not the paper's: the same runs check them. A rule holds when the runs agree "
                + "with it, fails when they contradict it; a rule the runs cannot test is not evaluated, with the reason.");
        b.table(List.of("rule", "verdict", "on all runs", "evidence", "how judged"), s.rules().stream()
                .map(r -> List.of(r.rule(), verdictCell(r.verdict(), r.caveats()), words(r.verdictAllRuns()),
                        r.evidence(), r.judgedBy())).toList());
    }

    /** @return e.g. {@code **mixed** (fragile: ...)}: the verdict in bold with its caveats */
    private static String verdictCell(String verdict, String caveats) {
        return "**" + words(verdict) + "**" + (caveats.isEmpty() ? "" : " (" + caveats + ")");
    }

    private static String words(String verdict) {
        return verdict == null ? NA : verdict.replace('_', ' ');
    }

    private static void robot(Blocks b, ExperimentSummary s) {
        b.heading(2, "The robot: completion, collisions, skipped releases and the mediator");
        b.text("Collisions over the runs that ended on the course; skipped releases are releases a task could not start "
                + "because its previous cycle was still running (they count as misses too); mediator cycles: how many "
                + "cycles the position mediator gave the obstacle avoider's request, the waypoint planner's, or a stop, "
                + "summed over the runs (empty where the run reports do not give them).");
        List<List<String>> rows = new ArrayList<>();
        for (SetSummary set : s.sets()) {
            Misses all = set.misses().get(ExperimentSummary.ALL_TASKS);
            Map<String, Long> m = set.mediatorCycles();
            rows.add(List.of(set.name(), new PeriodSet(set.name(), set.periodsMs()).shortLabel(),
                    set.topSpeedMps() == null ? "default" : PeriodSet.plainSpeed(set.topSpeedMps()),
                    set.completed() + " of " + set.runs(), set.runsWithCollisions() + " of " + set.measuredRuns(),
                    Long.toString(set.collisions()), all.skipped() == null ? NA : all.skipped() + " of " + all.releases(),
                    m.isEmpty() ? NA : RunResult.MEDIATOR_WINNERS.stream()
                            .map(w -> m.containsKey(w) ? Long.toString(m.get(w)) : NA).collect(java.util.stream.Collectors.joining(" / "))));
        }
        b.table(List.of("set", "periods (ms) w/o/oc/p", "top speed (m/s)", "completed", "runs with a collision", "collisions",
                "skipped releases (all four)", "mediator cycles obstacle / waypoint / stop"), rows);
    }

    private static void sweep(Blocks b, ExperimentSummary s) {
        if (SweepFigures.hasPeriodAxis(s)) {
            b.heading(2, "Against the period");
            List<String> off = s.sets().stream().filter(x -> x.sweptPeriodMs() == null).map(SetSummary::name).toList();
            b.text("The swept period is that of " + String.join(", ", s.sweptTasks()) + " (the tasks whose period differs "
                    + "between sets); the others keep theirs. "
                    + (off.isEmpty() ? "" : "Not on this axis (their swept tasks have different periods): "
                    + String.join(", ", off) + ". ") + "Completed: share of all runs; collided: share of the runs that ended "
                    + "on the course with at least one collision.");
            List<List<String>> rows = new ArrayList<>();
            s.sets().stream().filter(x -> x.sweptPeriodMs() != null)
                    .sorted(java.util.Comparator.comparing((SetSummary x) -> x.topSpeedMps() == null ? 0 : x.topSpeedMps())
                            .thenComparing(SetSummary::sweptPeriodMs))
                    .forEach(x -> rows.add(List.of(Long.toString(x.sweptPeriodMs()), x.name(),
                            x.topSpeedMps() == null ? "default" : PeriodSet.plainSpeed(x.topSpeedMps()),
                            rate(x.completionRate()), rate(x.collisionRate()), num(x.runTimeS().mean(), 2),
                            num(x.distanceToFinishM().mean(), 2),
                            num(x.misses().get(ExperimentSummary.ALL_TASKS).missPct(), 2), reactionBound(x))));
            b.table(List.of("period (ms)", "set", "top speed (m/s)", "completed", "collided", "mean run time (s)",
                    "mean distance to finish (m)", "misses, all four (%)", "largest safe period, reaction rule (ms)"), rows);
            b.figure(SweepFigures.PERIOD_RATES + ".png", "Completed and collided runs against the period (log axis)");
            b.figure(SweepFigures.PERIOD_RUNTIME + ".png", "Run time of the completed runs against the period");
            b.figure(SweepFigures.PERIOD_DISTANCE + ".png", "Distance from the finish against the period");
            b.figure(SweepFigures.PERIOD_MISSES + ".png", "Missed deadlines per task against the period");
        }
        if (SweepFigures.hasSpeedAxis(s)) {
            b.heading(2, "Against the top speed");
            String p = SweepFigures.SPEED_PREFIX;
            b.figure(p + "rates.png", "Completed and collided runs against the top speed");
            b.figure(p + "runtime.png", "Run time of the completed runs against the top speed");
            b.figure(p + "distance.png", "Distance from the finish against the top speed");
            b.figure(p + "misses.png", "Missed deadlines against the top speed");
        }
    }

    /** @return the reaction rule's largest safe period of the first task that has one, e.g. {@code 694.4 (obstacle)} */
    private static String reactionBound(SetSummary set) {
        for (String task : PeriodSet.TASKS) {
            Double bound = set.misses().get(task).maxSafePeriodMsMean();
            if (bound != null) {
                return num(bound, 1) + " (" + task + ")";
            }
        }
        return NA;
    }

    private static void completion(Blocks b, ExperimentSummary s) {
        b.heading(2, "Completion per set");
        b.text("The share of each set's runs that reached the finish, with its Wilson 95 % interval (summary.json: "
                + "`completion_rate`, `completion_rate_ci95`): an outcome of its own, since a run that got stuck, ran out "
                + "of time or failed has no run time and Table I leaves it out. Two sets whose intervals do not overlap "
                + "differ at about that confidence or better.");
        List<List<String>> rows = new ArrayList<>();
        for (SetSummary set : s.sets()) {
            RateInterval r = set.completions95();
            rows.add(List.of(set.name(), r == null ? NA : r.text(), outcomes(set.outcomes())));
        }
        b.table(List.of("set", "completed (rate, 95 % CI)", "outcomes"), rows);
    }

    private static String rate(Double share) {
        return share == null ? NA : num(100 * share, 0) + "%";
    }

    private static String name(ExperimentSummary s, int set) {
        return s.sets().stream().filter(x -> x.set() == set).map(SetSummary::name).findFirst().orElse("set " + set);
    }

    private static String outcomes(Map<String, Integer> outcomes) {
        List<String> parts = new ArrayList<>();
        outcomes.forEach((k, v) -> parts.add(v + " " + k));
        return String.join(", ", parts);
    }

    private static String missCell(Misses m) {
        return num(m.missPct(), 2) + " (" + m.misses() + " / " + m.releases() + ")";
    }

    private static String num(Double v, int decimals) {
        if (v == null || !Double.isFinite(v)) {
            return NA;
        }
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }
}
