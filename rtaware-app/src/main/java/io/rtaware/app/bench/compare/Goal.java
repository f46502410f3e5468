package io.rtaware.app.bench.compare;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One of issue 8's goals, checked against a comparison's numbers. Goals are printed as PASS or
 * MISS lines and written to the JSON; they never fail the command.
 *
 * @param goal what is promised
 * @param value the measured value, in the goal's terms
 * @param pass whether the goal holds in this run
 */
public record Goal(String goal, String value, boolean pass) {

    /** rtaware's p99 lateness may be at most this times the bare park loop's. */
    static final double MAX_P99_RATIO_TO_PARK_LOOP = 1.25;

    /**
     * @param runs the comparison's rows (executors missing from it are skipped)
     * @return the goals that can be checked with these rows
     */
    public static List<Goal> check(List<RunResult> runs) {
        RunResult rtaware = find(runs, "rtaware");
        RunResult stpe = find(runs, "stpe");
        RunResult park = find(runs, "park-loop");
        List<Goal> goals = new ArrayList<>();
        if (rtaware == null) {
            return goals;
        }
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
        return goals;
    }

    private static RunResult find(List<RunResult> runs, String executor) {
        return runs.stream().filter(r -> r.executor().equals(executor)).findFirst().orElse(null);
    }
}
