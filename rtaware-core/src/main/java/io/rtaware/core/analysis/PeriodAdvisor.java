package io.rtaware.core.analysis;

import io.rtaware.core.report.DataReport;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.Rounding;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ReactionConstraint;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Derives period advice from a finished run. Four rules applied to every periodic task, and one
 * to groups of them:
 * <ol>
 *   <li><b>nyquist</b>: a task that samples an input must run at least twice as fast as that
 *   input changes, so its period must be at most {@code 1 / (2 * rate)} of every key it
 *   consumes (the measured commit rate). A task slower than that (by more than
 *   {@value #TOLERANCE_PCT}% to absorb rate measurement noise) is told to shorten its period to
 *   the bound.</li>
 *   <li><b>mostly_stale</b>: a task whose runs are at least {@value #MOSTLY_STALE_PCT}% stale
 *   wakes mostly to no new data. It could run as slowly as the Nyquist bound of its fastest
 *   input; when that is at least {@value #MIN_SLOWDOWN} times its period, the advice says how
 *   much slower it could run and how much CPU time per second that frees, from the mean
 *   execution time: {@code exec_mean * (1/period - 1/suggested)}.</li>
 *   <li><b>exec_near_period</b>: a task whose p99 execution time is at least
 *   {@value #EXEC_NEAR_PERIOD_PCT}% of its period has no headroom. The suggested period puts the
 *   p99 at {@value #TARGET_EXEC_PCT}% of it. If that period would break the Nyquist bound of
 *   one of its inputs the advice says to do less work (to at most
 *   {@value #TARGET_EXEC_PCT}% of the period); otherwise it says to lengthen the period.</li>
 *   <li><b>reaction</b>, a rule from physics beside the Nyquist rule, for a task that declared a
 *   {@link ReactionConstraint} (it turns an input into motion): something that appears in the
 *   input at the declared range must be reacted to, and the motion stopped, before it is
 *   reached, so {@code speed * (period + input age p99) + stopping distance <= range}. The
 *   input's age at a read is its declared delay at commit plus the time since its last commit,
 *   whose p99 for reads that are not synchronized with the commits is {@code 0.99} of the
 *   measured commit interval ({@code 1 / rate}). The advice always names the largest safe
 *   period {@code 1000 * (range - stopping) / speed - age p99} ms, and says whether the task's
 *   period is within it.</li>
 *   <li><b>released_together</b>, once per group: at least {@value #MIN_TOGETHER} periodic tasks
 *   of one period and one offset are released at the same instants, so each release of the
 *   group is a burst that the cores (or a pool's workers) work off one task after the other.
 *   When the group's lateness p99 (the median over its tasks) is at least
 *   {@value #TOGETHER_LATENESS_PCT}% of the period, the advice names the task that starts latest
 *   (highest p50 lateness) and says to spread the group's offsets over the period. Reports that
 *   carry no offsets (written before the offset was reported) get no such advice.</li>
 * </ol>
 * Stateless and thread-safe.
 */
public final class PeriodAdvisor {

    /** Slack over the Nyquist bound before the nyquist rule fires, percent. */
    public static final double TOLERANCE_PCT = 2.0;
    /** Share of stale runs from which a task counts as mostly stale, percent. */
    public static final double MOSTLY_STALE_PCT = 50.0;
    /** How many times longer the Nyquist bound must be than the period to advise slowing down. */
    public static final double MIN_SLOWDOWN = 1.5;
    /** p99 execution time over period from which the exec rule fires, percent. */
    public static final double EXEC_NEAR_PERIOD_PCT = 80.0;
    /** p99 execution time over the suggested period, percent. */
    public static final double TARGET_EXEC_PCT = 70.0;
    /** Fewest tasks released at the same instants for the released_together rule. */
    public static final int MIN_TOGETHER = 4;
    /** Median over a group of its tasks' lateness p99, in percent of the period, from which released_together fires. */
    public static final double TOGETHER_LATENESS_PCT = 10.0;

    private PeriodAdvisor() {
    }

    /**
     * @param report a finished run
     * @return the advice, grouped by task in report order, then by rule
     */
    public static List<AdviceItem> advise(Report report) {
        List<AdviceItem> items = new ArrayList<>();
        for (TaskReport task : report.tasks()) {
            if (task.periodMs() == null || task.periodMs() <= 0) {
                continue;
            }
            List<DataReport> inputs = report.data().stream()
                    .filter(d -> d.consumers().contains(task.name())).toList();
            DataReport fastest = null;
            for (DataReport input : inputs) {
                if (input.rateHz() > 0 && (fastest == null || input.rateHz() > fastest.rateHz())) {
                    fastest = input;
                }
            }
            Double boundMs = fastest == null ? null : nyquistBoundMs(fastest.rateHz());
            nyquist(task, fastest, boundMs, items);
            mostlyStale(task, fastest, boundMs, items);
            execNearPeriod(task, fastest, boundMs, items);
            reaction(task, report, items);
        }
        releasedTogether(report, items);
        return items;
    }

    /**
     * @param rateHz an input's change rate
     * @return the longest period that samples it at least twice per change, in ms
     */
    public static double nyquistBoundMs(double rateHz) {
        return 1000.0 / (2.0 * rateHz);
    }

    private static void nyquist(TaskReport task, DataReport fastest, Double boundMs, List<AdviceItem> items) {
        double period = task.periodMs();
        if (boundMs == null || period <= boundMs * (1 + TOLERANCE_PCT / 100)) {
            return;
        }
        double suggested = floorTenth(boundMs);
        Map<String, Object> evidence = new LinkedHashMap<>();
        evidence.put("input", fastest.name());
        evidence.put("input_rate_hz", fastest.rateHz());
        evidence.put("nyquist_bound_ms", round3(boundMs));
        items.add(new AdviceItem(task.name(), "nyquist", period, suggested, evidence, String.format(Locale.ROOT,
                "'%s' samples '%s' (%.2f Hz) every %s ms; to see every change it must run at least twice as fast:"
                        + " period <= %s ms (suggest %s ms)",
                task.name(), fastest.name(), fastest.rateHz(), num(period), num(round3(boundMs)), num(suggested))));
    }

    private static void mostlyStale(TaskReport task, DataReport fastest, Double boundMs, List<AdviceItem> items) {
        if (task.runs() == 0 || boundMs == null) {
            return;
        }
        double stalePct = 100.0 * task.staleRuns() / task.runs();
        double period = task.periodMs();
        double suggested = floorTenth(boundMs);
        if (stalePct < MOSTLY_STALE_PCT || suggested < period * MIN_SLOWDOWN) {
            return;
        }
        double execMeanMs = task.execUs().mean() / 1000.0;
        double freedMsPerS = execMeanMs * (1000.0 / period - 1000.0 / suggested);
        Map<String, Object> evidence = new LinkedHashMap<>();
        evidence.put("stale_runs", task.staleRuns());
        evidence.put("runs", task.runs());
        evidence.put("stale_pct", round2(stalePct));
        evidence.put("input", fastest.name());
        evidence.put("input_rate_hz", fastest.rateHz());
        evidence.put("exec_mean_ms", round3(execMeanMs));
        evidence.put("slowdown_factor", round2(suggested / period));
        evidence.put("freed_cpu_ms_per_s", round2(freedMsPerS));
        items.add(new AdviceItem(task.name(), "mostly_stale", period, suggested, evidence, String.format(Locale.ROOT,
                "'%s' found no new data in %.0f%% of its runs: its fastest input '%s' changes at %.2f Hz, so it could"
                        + " run %.1fx slower (period %s ms instead of %s ms) and free %.2f ms of CPU per second",
                task.name(), stalePct, fastest.name(), fastest.rateHz(), suggested / period, num(suggested),
                num(period), freedMsPerS)));
    }

    private static void execNearPeriod(TaskReport task, DataReport fastest, Double boundMs, List<AdviceItem> items) {
        double period = task.periodMs();
        double p99Ms = task.execUs().p99() / 1000.0;
        double pct = 100.0 * p99Ms / period;
        if (pct < EXEC_NEAR_PERIOD_PCT) {
            return;
        }
        double suggested = ceilTenth(p99Ms / (TARGET_EXEC_PCT / 100));
        boolean periodBound = boundMs != null && suggested > boundMs * (1 + TOLERANCE_PCT / 100);
        double workTargetMs = round3(period * TARGET_EXEC_PCT / 100);
        Map<String, Object> evidence = new LinkedHashMap<>();
        evidence.put("exec_p99_ms", round3(p99Ms));
        evidence.put("exec_max_ms", round3(task.execUs().max() / 1000.0));
        evidence.put("exec_p99_pct_of_period", round2(pct));
        evidence.put("misses", task.misses());
        evidence.put("miss_pct", task.missPct());
        String message;
        if (periodBound) {
            evidence.put("input", fastest.name());
            evidence.put("nyquist_bound_ms", round3(boundMs));
            evidence.put("target_exec_ms", workTargetMs);
            message = String.format(Locale.ROOT,
                    "'%s' needs %s ms (p99) of its %s ms period (%.0f%%, %d misses); a longer period would break the"
                            + " Nyquist bound of '%s' (%s ms), so do less work: p99 <= %s ms",
                    task.name(), num(round3(p99Ms)), num(period), pct, task.misses(), fastest.name(),
                    num(round3(boundMs)), num(workTargetMs));
            suggested = period;
        } else {
            message = String.format(Locale.ROOT,
                    "'%s' needs %s ms (p99) of its %s ms period (%.0f%%, %d misses): lengthen the period to %s ms"
                            + " (or cut the work to p99 <= %s ms)",
                    task.name(), num(round3(p99Ms)), num(period), pct, task.misses(), num(suggested),
                    num(workTargetMs));
        }
        items.add(new AdviceItem(task.name(), "exec_near_period", period, suggested, evidence, message));
    }

    /**
     * @param constraint a declared reaction
     * @param inputRateHz the measured commit rate of its input (0 if unknown: no wait counted)
     * @return the input's age p99 at a read in ms: the declared delay plus 0.99 of one interval
     */
    public static double inputAgeP99Ms(ReactionConstraint constraint, double inputRateHz) {
        return constraint.inputDelayMs() + (inputRateHz > 0 ? 0.99 * 1000.0 / inputRateHz : 0.0);
    }

    private static void reaction(TaskReport task, Report report, List<AdviceItem> items) {
        ReactionConstraint r = task.reaction();
        if (r == null) {
            return;
        }
        double rate = report.data().stream().filter(d -> d.name().equals(r.input()))
                .mapToDouble(DataReport::rateHz).findFirst().orElse(0.0);
        double ageMs = inputAgeP99Ms(r, rate);
        double boundMs = r.maxPeriodMs(ageMs);
        double period = task.periodMs();
        double needM = r.closingSpeedMps() * (period + ageMs) / 1000.0 + r.stoppingDistanceM();
        Map<String, Object> evidence = new LinkedHashMap<>();
        evidence.put("input", r.input());
        evidence.put("input_rate_hz", rate);
        evidence.put("input_delay_ms", round3(r.inputDelayMs()));
        evidence.put("input_age_p99_ms", round3(ageMs));
        evidence.put("speed_mps", r.speedMps());
        evidence.put("obstacle_speed_mps", r.obstacleSpeedMps());
        evidence.put("closing_speed_mps", r.closingSpeedMps());
        evidence.put("assumption", r.obstacleAssumption());
        evidence.put("stopping_distance_m", round3(r.stoppingDistanceM()));
        evidence.put("range_m", r.rangeM());
        evidence.put("needed_m", round3(needM));
        evidence.put("max_safe_period_ms", round3(boundMs));
        evidence.put("safe", boundMs > 0 && period <= boundMs);
        String message;
        double suggested;
        if (boundMs <= 0) {
            suggested = period;
            message = String.format(Locale.ROOT,
                    "'%s' cannot react in time at any period: at %s m/s the input's age (%s ms p99) and the stopping"
                            + " distance (%s m) already use up the %s m range; lower the speed or extend the range (%s)",
                    task.name(), num(r.closingSpeedMps()), num(round3(ageMs)), num(round3(r.stoppingDistanceM())),
                    num(r.rangeM()), r.obstacleAssumption());
        } else {
            suggested = Math.min(period, floorTenth(boundMs));
            message = String.format(Locale.ROOT,
                    "'%s' must react within %s m at %s m/s: %s m/s x (%s ms period + %s ms input age p99) + %s m stopping"
                            + " = %s m; the largest safe period is %s ms (%s; %s)",
                    task.name(), num(r.rangeM()), num(r.closingSpeedMps()), num(r.closingSpeedMps()), num(period),
                    num(round3(ageMs)), num(round3(r.stoppingDistanceM())), num(round3(needM)),
                    num(floorTenth(boundMs)), period <= boundMs ? "the period is within it" : "shorten the period",
                    r.obstacleAssumption());
        }
        items.add(new AdviceItem(task.name(), "reaction", period, suggested, evidence, message));
    }

    private static void releasedTogether(Report report, List<AdviceItem> items) {
        // Groups by period and by the phase of the first release within it, in nanoseconds (the
        // unit periods are declared in: any period of at least 1 ns has a phase).
        Map<String, List<TaskReport>> groups = new LinkedHashMap<>();
        for (TaskReport task : report.tasks()) {
            if (task.periodMs() == null || task.offsetMs() == null || task.latenessUs() == null) {
                continue; // a report without offsets or lateness (lateness_us is optional): no such advice
            }
            long periodNs = Math.round(task.periodMs() * 1e6);
            if (periodNs <= 0) {
                continue;
            }
            groups.computeIfAbsent(periodNs + "/" + phaseNs(task.offsetMs(), periodNs), k -> new ArrayList<>()).add(task);
        }
        for (List<TaskReport> group : groups.values()) {
            if (group.size() < MIN_TOGETHER) {
                continue;
            }
            double period = group.get(0).periodMs();
            double[] p99s = group.stream().mapToDouble(t -> t.latenessUs().p99() / 1000.0).sorted().toArray();
            double medianP99Ms = p99s.length % 2 == 1 ? p99s[p99s.length / 2]
                    : (p99s[p99s.length / 2 - 1] + p99s[p99s.length / 2]) / 2;
            double pct = 100.0 * medianP99Ms / period;
            if (pct < TOGETHER_LATENESS_PCT) {
                continue;
            }
            TaskReport latest = group.get(0);
            TaskReport first = group.get(0);
            for (TaskReport t : group) {
                if (t.latenessUs().p50() > latest.latenessUs().p50()) {
                    latest = t;
                }
                if (t.latenessUs().p50() < first.latenessUs().p50()) {
                    first = t;
                }
            }
            double offset = phaseNs(group.get(0).offsetMs(), Math.round(period * 1e6)) / 1e6;
            double stepMs = round3(period / group.size());
            Map<String, Object> evidence = new LinkedHashMap<>();
            evidence.put("tasks_released_together", group.size());
            evidence.put("offset_ms", round3(offset));
            evidence.put("lateness_p99_median_ms", round3(medianP99Ms));
            evidence.put("lateness_p99_median_pct_of_period", round2(pct));
            evidence.put("first_task", first.name());
            evidence.put("first_lateness_p50_ms", round3(first.latenessUs().p50() / 1000.0));
            evidence.put("latest_lateness_p50_ms", round3(latest.latenessUs().p50() / 1000.0));
            evidence.put("suggested_offset_step_ms", stepMs);
            items.add(new AdviceItem(latest.name(), "released_together", period, period, evidence,
                    String.format(Locale.ROOT,
                            "'%s' and %d other tasks of period %s ms are released at the same instant (offset %s ms) and"
                                    + " wait for each other: lateness p99 %s ms (median over them, %.0f%% of the period),"
                                    + " p50 from %s ms ('%s') to %s ms ('%s'); spread their offsets over the period"
                                    + " (Schedule.periodic(period, offset, deadline)), e.g. %s ms apart",
                            latest.name(), group.size() - 1, num(period), num(round3(offset)),
                            num(round3(medianP99Ms)), pct, num(round3(first.latenessUs().p50() / 1000.0)),
                            first.name(), num(round3(latest.latenessUs().p50() / 1000.0)), latest.name(),
                            num(stepMs))));
        }
    }

    /** @return where within a period of {@code periodNs} (at least 1) an offset falls, in ns */
    private static long phaseNs(double offsetMs, long periodNs) {
        return Math.floorMod(Math.round(offsetMs * 1e6), periodNs);
    }

    static double floorTenth(double ms) {
        return Math.max(0.1, Math.floor(ms * 10 + 1e-9) / 10);
    }

    static double ceilTenth(double ms) {
        return Math.ceil(ms * 10 - 1e-9) / 10;
    }

    static double round2(double v) {
        return Rounding.toDecimals(v, 2);
    }

    static double round3(double v) {
        return Rounding.toDecimals(v, 3);
    }

    /** Milliseconds for a message: up to three decimals, never a dangling point; tiny values in %g. */
    static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        if (v != 0 && Math.abs(v) < 0.0005 || !Double.isFinite(v) || Math.abs(v) >= 1e15) {
            return String.format(Locale.ROOT, "%.3g", v);
        }
        return String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "").replaceAll("\\.$", "");
    }
}
