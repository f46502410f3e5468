package io.rtaware.bench.compare;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One of issue 8's and issue 16's goals, checked against a comparison's numbers. Goals are printed as PASS or
 * MISS lines and written to the JSON; they never fail the command.
 *
 * @param goal what is promised
 * @param value the measured value, in the goal's terms
 * @param pass whether the goal holds in this run
 */
public record Goal(String goal, String value, boolean pass) {

    /** rtaware's p99 lateness may be at most this times the bare park loop's. */
    static final double MAX_P99_RATIO_TO_PARK_LOOP = 1.25;
    /** Issue 16: rtaware's misses and p99.9 may be at most this times the bare park loop's. */
    static final double MAX_RATIO_TO_PARK_LOOP = 1.5;
    /** Issue 16: misses below this share of releases (idle machine). */
    static final double MAX_MISS_PCT = 1.0;

    /**
     * @param runs the comparison's rows (executors missing from it are skipped)
     * @return the goals that can be checked with these rows
     */
    public static List<Goal> check(List<RunResult> runs) {
        RunResult rtaware = find(runs, "rtaware");
        RunResult stpe = find(runs, "stpe");
        RunResult park = find(runs, "park-loop");
        List<Goal> goals = new ArrayList<>();
        if (rtaware != null) {
            issue8(rtaware, stpe, park, goals);
        }
        RunResult pooled = find(runs, "rtaware-pooled");
        if (rtaware != null && park != null) {
            // The ratio of two totals near overload swings from run to run: its interval over the
            // rounds says how far this run's value can be trusted.
            String interval = PairedRounds.compare(rtaware, park).map(p -> "; " + p.interval()).orElse("");
            goals.add(ratioGoal("rtaware misses / park-loop misses", rtaware.misses(), park.misses(),
                    MAX_RATIO_TO_PARK_LOOP, interval));
            goals.add(ratioGoal("rtaware p99.9 / park-loop p99.9", rtaware.latenessUs().p999(),
                    park.latenessUs().p999(), MAX_RATIO_TO_PARK_LOOP, ""));
            goals.add(missShare("rtaware", rtaware));
        }
        if (pooled != null) {
            goals.add(missShare("rtaware-pooled", pooled));
            RunResult peer = find(runs, "stpe-pooled");
            if (peer != null) {
                goals.add(notWorse("rtaware-pooled p99 <= stpe-pooled p99", pooled.latenessUs().p99(),
                        peer.latenessUs().p99()));
                goals.add(notWorse("rtaware-pooled p99.9 <= stpe-pooled p99.9", pooled.latenessUs().p999(),
                        peer.latenessUs().p999()));
                goals.add(new Goal("rtaware-pooled misses <= stpe-pooled misses",
                        pooled.misses() + " vs " + peer.misses(), pooled.misses() <= peer.misses()));
            }
        }
        return goals;
    }

    /** Issue 8's goals for the threaded executor, in their original order. */
    private static void issue8(RunResult rtaware, RunResult stpe, RunResult park, List<Goal> goals) {
        double p99 = rtaware.latenessUs().p99();
        if (park != null) {
            double floor = park.latenessUs().p99();
            double ratio = floor > 0 ? p99 / floor : (p99 > 0 ? Double.POSITIVE_INFINITY : 1.0);
            goals.add(new Goal("rtaware p99 / park-loop p99 <= " + MAX_P99_RATIO_TO_PARK_LOOP,
                    String.format(Locale.ROOT, "%.2f (%.1f / %.1f us)", ratio, p99, floor),
                    ratio <= MAX_P99_RATIO_TO_PARK_LOOP));
        }
        if (stpe != null) {
            double other = stpe.latenessUs().p99();
            goals.add(new Goal("rtaware p99 <= stpe p99",
                    String.format(Locale.ROOT, "%.1f us vs %.1f us", p99, other), p99 <= other));
        }
        goals.add(new Goal("zero bursts (rtaware)", Long.toString(rtaware.bursts()), rtaware.bursts() == 0));
        goals.add(new Goal("zero framework bytes per release (rtaware)",
                String.format(Locale.ROOT, "%.1f B", rtaware.allocBytesPerRelease()),
                rtaware.allocBytesPerRelease() == 0));
    }

    /** @param detail appended inside the value's parentheses (empty for none) */
    private static Goal ratioGoal(String what, double value, double floor, double max, String detail) {
        double ratio = PairedRounds.ratio(value, floor);
        return new Goal(what + " <= " + max, String.format(Locale.ROOT, "%.2f (%s / %s%s)", ratio, num(value),
                num(floor), detail), ratio <= max);
    }

    private static Goal notWorse(String what, double value, double other) {
        return new Goal(what, String.format(Locale.ROOT, "%.1f us vs %.1f us", value, other), value <= other);
    }

    private static Goal missShare(String executor, RunResult run) {
        double pct = run.releases() == 0 ? 0 : 100.0 * run.misses() / run.releases();
        return new Goal(executor + " misses < " + MAX_MISS_PCT + " % of releases",
                String.format(Locale.ROOT, "%.2f %%", pct), pct < MAX_MISS_PCT);
    }

    private static String num(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : String.format(Locale.ROOT, "%.1f", v);
    }

    private static RunResult find(List<RunResult> runs, String executor) {
        return runs.stream().filter(r -> r.executor().equals(executor)).findFirst().orElse(null);
    }
}
