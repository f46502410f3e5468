package io.rtaware.experiment.claims;

import io.rtaware.experiment.Decimals;
import io.rtaware.experiment.ExperimentSummary.PairTest;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.PaperReference;
import io.rtaware.experiment.PeriodSet;
import io.rtaware.experiment.RunResult;
import io.rtaware.experiment.stats.WelchTest;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Function;
import java.util.function.ToIntFunction;

/**
 * One judging of an experiment's results: what the claim families read (the sets, their Welch
 * tests, the course, the paper's sets among them) and where their verdicts go.
 */
final class Judging {

    private final List<SetSummary> sets;
    private final Map<String, List<PairTest>> tests;
    private final List<RunResult> rows;
    private final String scenario;
    private final Map<Integer, SetSummary> paper;
    /** The CPU quota every run ran under, or null: see {@link #cpuQuota()}. */
    private final Double cpuQuota;
    private final List<Claim> claims = new ArrayList<>();
    private final List<NotEvaluated> notEvaluated = new ArrayList<>();

    Judging(PaperClaims.Results results, String scenario) {
        this.sets = results.sets();
        this.tests = results.tests();
        this.rows = results.rows();
        this.scenario = scenario;
        this.paper = paperSets(sets);
        List<Double> quotas = rows.stream().map(r -> r.conditions().cpuLimitCpus()).distinct().toList();
        this.cpuQuota = quotas.size() == 1 ? quotas.get(0) : null;
    }

    /** @return every set of the experiment, in set order */
    List<SetSummary> sets() {
        return sets;
    }

    /** @return the runs the sets summarize */
    List<RunResult> rows() {
        return rows;
    }

    /** @return the paper's set number to our set with its periods at the paper's top speed */
    Map<Integer, SetSummary> paper() {
        return paper;
    }

    /** @return the sets per top speed in words ({@link #speedLabel}), in set order */
    Map<String, List<SetSummary>> bySpeed() {
        Map<String, List<SetSummary>> bySpeed = new LinkedHashMap<>();
        sets.forEach(s -> bySpeed.computeIfAbsent(speedLabel(s.topSpeedMps()), k -> new ArrayList<>()).add(s));
        return bySpeed;
    }

    /**
     * @param base the scope before the speed
     * @param speed a key of {@link #bySpeed()}
     * @return {@code base} at that speed when the sets differ in speed, else {@code base}
     */
    Scope atSpeed(Scope base, String speed) {
        return bySpeed().size() > 1 ? base.at(speed) : base;
    }

    /** @return the paper's scope on this experiment's course */
    Scope course() {
        return Scope.PAPER.on(scenario);
    }

    /**
     * @param rule the claim's family
     * @param scope what it was judged on besides the paper's course and speed
     * @param verdict the verdict
     * @param evidence the numbers
     * @param how how the verdict follows from them
     * @param cells the sets the verdict rests on
     * @param perCell the runs (or blocks) of a set that count for this verdict
     */
    void judged(ClaimRule rule, Scope scope, Verdict verdict, String evidence, String how, List<SetSummary> cells,
                ToIntFunction<SetSummary> perCell) {
        Integer fewest = cells.isEmpty() ? null : cells.stream().mapToInt(perCell).min().orElseThrow();
        claims.add(new Claim(rule.id() + scope.idSuffix(), rule.statement() + scope.words(), verdict, evidence, how, null,
                false, fewest, fewest != null && fewest < PaperClaims.SMALL_SAMPLE_RUNS, rule.id(), conditions(cells),
                cells.stream().map(Judging::cell).distinct().toList()));
    }

    void unjudged(ClaimRule rule, Scope scope, String reason) {
        notEvaluated.add(new NotEvaluated(rule.id() + scope.idSuffix(), rule.statement() + scope.words(), reason, null,
                false));
    }

    /** @return the tasks whose period differs between the sets, in task order */
    List<String> sweptTasks() {
        return PeriodSet.TASKS.stream()
                .filter(t -> sets.stream().map(s -> s.periodsMs().get(t)).distinct().count() > 1).toList();
    }

    /**
     * @param verdicts the verdicts of the groups of one claim (per top speed), at least one
     * @return their common verdict, or mixed when they differ
     */
    static Verdict combine(List<Verdict> verdicts) {
        return verdicts.stream().distinct().count() == 1 ? verdicts.get(0) : Verdict.MIXED;
    }

    /** @return e.g. {@code 200/300/500/800 ms at 0.4 m/s}: a set as its periods in task order and its top speed */
    static String cell(SetSummary set) {
        return String.join("/", PeriodSet.TASKS.stream().map(t -> String.valueOf(set.periodsMs().get(t))).toList())
                + " ms at " + speedLabel(set.topSpeedMps());
    }

    /**
     * @return e.g. {@code office at 0.4 m/s, swept: obstacle} (and {@code , under 1 CPU} with a CPU quota): the
     *     conditions shared by experiments that agree
     */
    private String conditions(List<SetSummary> cells) {
        String speeds = String.join(", ", cells.stream().map(s -> speedLabel(s.topSpeedMps())).distinct().toList());
        List<String> swept = sweptTasks();
        return (scenario == null ? Scope.PAPER_COURSE : scenario) + " at " + speeds + ", swept: "
                + (swept.isEmpty() ? "none" : String.join("+", swept))
                + (cpuQuota == null ? "" : ", under " + Decimals.plain(cpuQuota) + " CPU");
    }

    /**
     * @return the CPU quota every run's JVM ran under ({@code --cpu-limit}), or null when a run had none or the
     *     runs differ (an experiment is made with one quota or none; merged folders must agree)
     */
    Double cpuQuota() {
        return cpuQuota;
    }

    List<Claim> claims() {
        return List.copyOf(claims);
    }

    List<NotEvaluated> notEvaluated() {
        return List.copyOf(notEvaluated);
    }

    /**
     * @param a a paper set's number
     * @param b another
     * @param quantity a key of the tests
     * @return the Welch test between our sets with those periods, or null when one was not run
     */
    WelchTest test(int a, int b, String quantity) {
        SetSummary x = paper.get(a);
        SetSummary y = paper.get(b);
        if (x == null || y == null) {
            return null;
        }
        for (PairTest p : tests.getOrDefault(quantity, List.of())) {
            if (p.setA() == x.set() && p.setB() == y.set() || p.setA() == y.set() && p.setB() == x.set()) {
                return p.test();
            }
        }
        return null;
    }

    /** @return why the test of a pair of paper sets cannot be read, or null when it can */
    String missing(int[] pair, WelchTest t) {
        for (int n : pair) {
            if (!paper.containsKey(n)) {
                return "the paper's Set " + n + " (" + PaperReference.published().sets().get(n - 1).periods().shortLabel()
                        + " ms at the paper's top speed) was not run";
            }
        }
        if (t == null || !t.applicable()) {
            return "the t-test of Set " + pair[0] + " vs Set " + pair[1] + " is not defined"
                    + (t == null ? "" : ": " + t.note());
        }
        return null;
    }

    /** @return e.g. {@code Set 2 (our "obstacle 10 ms"), Set 5}: the paper's numbers, with our name where it differs */
    String names(List<Integer> numbers) {
        return String.join(", ", numbers.stream().map(n -> {
            String ours = paper.get(n).name();
            return ours.equals("Set " + n) ? "Set " + n : "Set " + n + " (our '" + ours + "')";
        }).toList());
    }

    /**
     * @param numbers paper set numbers; none for all of them
     * @return our sets with those periods that were run, in the order given
     */
    List<SetSummary> paperSets(int... numbers) {
        if (numbers.length == 0) {
            return List.copyOf(paper.values());
        }
        return java.util.Arrays.stream(numbers).mapToObj(paper::get).filter(java.util.Objects::nonNull).toList();
    }

    /** @return the paper sets present in words, or {@code none} */
    String paperNames() {
        return paper.isEmpty() ? "none" : names(new ArrayList<>(paper.keySet()));
    }

    private static Map<Integer, SetSummary> paperSets(List<SetSummary> sets) {
        Map<Integer, SetSummary> paper = new TreeMap<>();
        List<PaperReference.PaperSet> published = PaperReference.published().sets();
        for (SetSummary s : sets) {
            PaperReference.PaperSet match = s.paperSet();
            if (match != null) {
                paper.putIfAbsent(published.indexOf(match) + 1, s);
            }
        }
        return paper;
    }

    /** @return the sets on the period axis (their swept tasks share one period) */
    static List<SetSummary> onAxis(List<SetSummary> group) {
        return group.stream().filter(s -> s.sweptPeriodMs() != null).toList();
    }

    /** @return the periods of a group, for a reason, e.g. {@code " (periods here: 10 ms, 50 ms)"} */
    static String periodsHere(List<SetSummary> group) {
        List<Long> periods = onAxis(group).stream().map(SetSummary::sweptPeriodMs).distinct().sorted().toList();
        return periods.isEmpty() ? " (the sets do not differ in one swept period)"
                : " (periods here: " + String.join(", ", periods.stream().map(p -> p + " ms").toList()) + ")";
    }

    /** @return the paper set number with the highest score */
    static int argBest(Map<Integer, SetSummary> paper, Function<SetSummary, Double> score) {
        return paper.entrySet().stream().max(Comparator.comparingDouble(e -> score.apply(e.getValue())))
                .orElseThrow().getKey();
    }

    /** @return (largest - smallest) / mean of the sets' means */
    static double spread(List<SetSummary> sets, Function<SetSummary, Double> mean) {
        double max = sets.stream().mapToDouble(mean::apply).max().orElseThrow();
        double min = sets.stream().mapToDouble(mean::apply).min().orElseThrow();
        double avg = sets.stream().mapToDouble(mean::apply).average().orElseThrow();
        return (max - min) / avg;
    }

    static String speedLabel(Double speedMps) {
        return speedMps == null ? "run's default top speed" : PeriodSet.plainSpeed(speedMps) + " m/s";
    }

    static String pct(double share) {
        return num(100 * share, 1) + "%";
    }

    static String num(Double v, int decimals) {
        return v == null || !Double.isFinite(v) ? "n/a" : String.format(Locale.ROOT, "%." + decimals + "f", v);
    }
}
