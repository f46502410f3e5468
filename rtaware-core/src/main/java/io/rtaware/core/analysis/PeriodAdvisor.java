package io.rtaware.core.analysis;

import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.report.DataReport;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ReactionConstraint;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * One period per periodic task, from every rule at once. For each task the rules give bounds on
 * its period, each named with its figure ({@link PeriodBound}):
 * <ul>
 *   <li>lower, <b>exec</b>: the task's p99 execution time must fit in its deadline (the deadline
 *   keeps its ratio to the period);</li>
 *   <li>lower, <b>response_time</b>: the task's response time in the whole set, on the cores it
 *   may use ({@link Schedulability}: exact on one core, the global fixed-priority bound of
 *   Bertogna and Cirinei, sufficient only, on more), must fit in its deadline. Under
 *   rate-monotonic priorities a longer period is a lower priority, so the bound is the least
 *   period from which every longer one clears the task, the other tasks at their suggested
 *   periods;</li>
 *   <li>upper, <b>sampling</b>, once per input: a task that samples an input must run at least
 *   twice as fast as the input changes, {@code period <= 1 / (2 * rate)}, the rate measured (and,
 *   where the input's producer is a periodic task whose period the advice changes, scaled by
 *   the ratio of its periods), but never more than the fastest of the producer's own inputs
 *   changes: a task that commits faster than its inputs change repeats their information;</li>
 *   <li>upper, <b>reaction</b>, for a task that declared a {@link ReactionConstraint}:
 *   {@code speed * (period + input age p99) + stopping distance <= range}, the input's age at a
 *   read being its declared delay plus 0.99 of its commit interval;</li>
 *   <li>upper, <b>freshness</b>, once per consumer that declared a maximum age of what the task
 *   produces ({@code TaskSetup.consume(key, maxAge)}): between two commits the value's age
 *   reaches the period plus the producer's execution time (a cycle that commits early, then one
 *   that commits late), so {@code period <= max age - exec p99}.</li>
 * </ul>
 * The period chosen in the interval: the run's when it lies within it (upper bounds get
 * {@value #TOLERANCE_PCT}% for the noise of a measured rate), unless its p99 execution time
 * takes {@value #EXEC_NEAR_PERIOD_PCT}% of it or more (then the period that puts it at
 * {@value #TARGET_EXEC_PCT}%, as far as the upper bounds allow) or at least
 * {@value #MOSTLY_STALE_PCT}% of its runs were stale and the upper bound is at least
 * {@value #MIN_SLOWDOWN} times the period (then the upper bound, which frees CPU time); the
 * upper bound when the period is above it; the lower bound, or the headroom target, when below.
 * Suggested periods keep three significant digits, rounded into the interval. Where the
 * interval is empty the verdict is {@link PeriodAdvice#INFEASIBLE}, the advice names the two
 * bounds that collide and what would open the interval, and the suggestion is the least period
 * the task needs, never less.
 *
 * <p>The periods are chosen together: producers before consumers (a consumer's sampling bound
 * follows its producer's suggested period), then the whole set is checked; while a task fails
 * the response-time test, its response-time bound is raised to the least period that clears it
 * and the choice runs again (sets of more than {@value #MAX_SEARCHED_TASKS} tasks are checked,
 * not searched). The advice ends with the schedulability of the suggested set
 * ({@link Advice#suggestedSet()}).
 *
 * <p>When the run's machine was busy or disturbed, its execution times hold the machine's share
 * too: a longer period that rests on them is not suggested (verdict
 * {@link PeriodAdvice#MACHINE}), nor is advice on release offsets, which rests on lateness.
 *
 * <p>A note beside a period, {@code released_together}: at least {@value #MIN_TOGETHER} periodic
 * tasks of one period and one offset are released at the same instants, and the group's
 * lateness p99 (median over its tasks) is at least {@value #TOGETHER_LATENESS_PCT}% of the
 * period: the note, on the task that starts latest, says to spread their offsets.
 *
 * <p>A pure function of the report, the core count and the machine verdict. Stateless and
 * thread-safe.
 */
public final class PeriodAdvisor {

    /** Slack over an upper bound before a period counts as beyond it, percent. */
    public static final double TOLERANCE_PCT = 2.0;
    /** Share of stale runs from which a task counts as mostly stale, percent. */
    public static final double MOSTLY_STALE_PCT = 50.0;
    /** How many times longer the upper bound must be than the period to advise a mostly stale task to slow down. */
    public static final double MIN_SLOWDOWN = 1.5;
    /** p99 execution time over the deadline from which the period counts as without headroom, percent. */
    public static final double EXEC_NEAR_PERIOD_PCT = 80.0;
    /** p99 execution time over the deadline of a period suggested for headroom, percent. */
    public static final double TARGET_EXEC_PCT = 70.0;
    /** Fewest tasks released at the same instants for the released_together note. */
    public static final int MIN_TOGETHER = 4;
    /** Median over a group of its tasks' lateness p99, in percent of the period, from which released_together notes. */
    public static final double TOGETHER_LATENESS_PCT = 10.0;
    /** The most periodic tasks whose response-time bounds are searched; a larger set is only checked. */
    public static final int MAX_SEARCHED_TASKS = 64;

    /** Why a period grows. */
    private enum Reason { NONE, LOWER, HEADROOM, STALE }

    private PeriodAdvisor() {
    }

    /**
     * @param report a finished run
     * @param cores the cores the tasks may use, at least 1
     * @return the advice, on a machine of unknown verdict
     */
    public static Advice advise(Report report, int cores) {
        return advise(report, cores, null);
    }

    /**
     * @param report a finished run
     * @param cores the cores the tasks may use, at least 1
     * @param machine the run's machine verdict, or null when unknown
     * @return one item per periodic task, in report order, and the check of the suggested set
     */
    public static Advice advise(Report report, int cores, MachineVerdict machine) {
        return advise(report, cores, machine, Map.of());
    }

    /**
     * The advice made again with some changes withdrawn (a what-if replay showed them worse):
     * those tasks keep their period, and the others are advised around it, so no bound rests on
     * a change that is not made.
     *
     * @param report a finished run
     * @param cores the cores the tasks may use, at least 1
     * @param machine the run's machine verdict, or null when unknown
     * @param withdrawn items already withdrawn ({@link PeriodAdvice#withdrawn}), by task: each
     *     task keeps its period and its item is this one
     * @return one item per periodic task, in report order, and the check of the suggested set
     */
    public static Advice advise(Report report, int cores, MachineVerdict machine, Map<String, PeriodAdvice> withdrawn) {
        if (cores < 1) {
            throw new IllegalArgumentException("cores must be at least 1, got " + cores);
        }
        boolean inflated = machine != null && (MachineVerdict.BUSY.equals(machine.verdict())
                || MachineVerdict.DISTURBED.equals(machine.verdict()));
        String machineWhy = inflated ? machine.verdict() + " (" + String.join("; ", machine.reasons()) + ")" : "";
        List<Plan> plans = new ArrayList<>();
        Map<String, Plan> byName = new HashMap<>();
        for (TaskReport t : report.tasks()) {
            if (t.periodMs() != null && t.periodMs() > 0) {
                Plan p = new Plan(t, plans.size());
                plans.add(p);
                byName.put(t.name(), p);
            }
        }
        for (DataReport d : report.data()) {
            Plan producer = byName.get(d.producer());
            if (producer != null) {
                producer.outputs.add(d);
            }
            for (String consumer : d.consumers()) {
                Plan p = byName.get(consumer);
                if (p != null && !consumer.equals(d.producer())) {
                    p.inputs.add(d);
                }
            }
        }
        List<Plan> order = producersFirst(plans, byName);
        boolean search = plans.size() <= MAX_SEARCHED_TASKS;
        Set<Plan> stuck = new HashSet<>();
        for (Plan p : plans) {
            if (withdrawn.containsKey(p.name())) {
                stuck.add(p); // its period stays whatever the set asks
            }
        }
        for (int round = 0; ; round++) {
            for (Plan p : order) {
                choose(p, report, byName, inflated);
                if (withdrawn.containsKey(p.name())) {
                    p.chosenMs = p.periodMs;
                }
            }
            if (!search || round > plans.size() + 16) {
                break;
            }
            Plan failing = firstFailing(plans, cores, stuck);
            if (failing == null) {
                break;
            }
            double need = responseLowerBoundMs(failing, plans, cores);
            if (failing.held || !(need > failing.responseLowerMs)) {
                stuck.add(failing);
            } else {
                failing.responseLowerMs = need;
            }
        }
        Map<String, Double> chosen = new LinkedHashMap<>();
        plans.forEach(p -> chosen.put(p.name(), p.chosenMs));
        SchedulabilityReport suggested = Schedulability.analyze(report, chosen, cores);
        Map<String, TaskUtilization> rows = new HashMap<>();
        suggested.tasks().forEach(row -> rows.put(row.task(), row));
        Map<String, AdviceNote> together = releasedTogether(report, inflated, machineWhy);
        List<PeriodAdvice> items = new ArrayList<>();
        for (Plan p : plans) {
            if (p.responseLowerMs > 0 && Double.isFinite(p.responseLowerMs)) {
                p.responseLowerMs = responseLowerBoundMs(p, plans, cores); // the others have settled since
            }
            PeriodAdvice item = withdrawn.get(p.name());
            items.add(item != null ? item
                    : finish(p, rows.get(p.task.name()), cores, together.get(p.task.name()), machineWhy));
        }
        return new Advice(cores, items, suggested);
    }

    /**
     * @param rateHz an input's change rate
     * @return the longest period that samples it at least twice per change, in ms
     */
    public static double samplingBoundMs(double rateHz) {
        return 1000.0 / (2.0 * rateHz);
    }

    /**
     * @param constraint a declared reaction
     * @param inputRateHz the commit rate of its input (0 if unknown: no wait counted)
     * @return the input's age p99 at a read in ms: the declared delay plus 0.99 of one interval
     */
    public static double inputAgeP99Ms(ReactionConstraint constraint, double inputRateHz) {
        return constraint.inputDelayMs() + (inputRateHz > 0 ? 0.99 * 1000.0 / inputRateHz : 0.0);
    }

    /** One periodic task while its period is chosen. */
    private static final class Plan {
        final TaskReport task;
        /** Position among the periodic tasks, in report order. */
        final int index;
        final double periodMs;
        /** Deadline over period. */
        final double ratio;
        final double execMs;
        final List<DataReport> inputs = new ArrayList<>();
        final List<DataReport> outputs = new ArrayList<>();
        double chosenMs;
        /** The response-time bound the set has asked for so far, ms; infinite when no period clears the task. */
        double responseLowerMs;
        String verdict;
        Reason reason = Reason.NONE;
        /** True when the machine holds back the change the figures ask for. */
        boolean held;
        List<PeriodBound> upper = List.of();

        Plan(TaskReport task, int index) {
            this.task = task;
            this.index = index;
            this.periodMs = task.periodMs();
            this.ratio = task.deadlineMs() == null ? 1.0 : task.deadlineMs() / task.periodMs();
            this.execMs = task.execUs().p99() / 1000.0;
            this.chosenMs = periodMs;
        }

        String name() {
            return task.name();
        }

        double execLowerMs() {
            return execMs / ratio;
        }

        double lowerMs() {
            return Math.max(execLowerMs(), responseLowerMs);
        }

        double stalePct() {
            return task.runs() == 0 ? 0 : 100.0 * task.staleRuns() / task.runs();
        }
    }

    /**
     * Producers before their consumers, report order among the tasks ready at once; a cycle of
     * tasks that consume each other is broken at its task first in report order.
     */
    private static List<Plan> producersFirst(List<Plan> plans, Map<String, Plan> byName) {
        Map<Plan, Set<Plan>> producers = new HashMap<>();
        Map<Plan, List<Plan>> consumers = new HashMap<>();
        for (Plan p : plans) {
            Set<Plan> of = new HashSet<>();
            for (DataReport d : p.inputs) {
                Plan producer = byName.get(d.producer());
                if (producer != null && of.add(producer)) {
                    consumers.computeIfAbsent(producer, k -> new ArrayList<>()).add(p);
                }
            }
            producers.put(p, of);
        }
        TreeSet<Integer> left = new TreeSet<>();
        TreeSet<Integer> ready = new TreeSet<>();
        for (Plan p : plans) {
            left.add(p.index);
            if (producers.get(p).isEmpty()) {
                ready.add(p.index);
            }
        }
        List<Plan> order = new ArrayList<>();
        while (!left.isEmpty()) {
            Plan next = plans.get(ready.isEmpty() ? left.first() : ready.first());
            ready.remove(next.index);
            left.remove(next.index);
            order.add(next);
            for (Plan c : consumers.getOrDefault(next, List.of())) {
                producers.get(c).remove(next);
                if (producers.get(c).isEmpty() && left.contains(c.index)) {
                    ready.add(c.index);
                }
            }
        }
        return order;
    }

    private static void choose(Plan p, Report report, Map<String, Plan> byName, boolean inflated) {
        p.upper = upperBounds(p, report, byName);
        PeriodBound binding = tightest(p.upper);
        double hi = binding == null ? Double.POSITIVE_INFINITY : binding.ms();
        double lo = p.lowerMs();
        double run = p.periodMs;
        double slack = 1 + TOLERANCE_PCT / 100;
        p.reason = Reason.NONE;
        if (Double.isInfinite(lo)) {
            p.verdict = PeriodAdvice.INFEASIBLE;
            p.chosenMs = run;
        } else if (lo > hi * slack || hi <= 0) {
            p.verdict = PeriodAdvice.INFEASIBLE;
            p.chosenMs = Num.ceilPeriod(lo);
        } else if (run > hi * slack) {
            p.verdict = PeriodAdvice.SHORTEN;
            p.chosenMs = within(Num.floorPeriod(hi), lo, hi);
        } else if (run < lo) {
            p.verdict = PeriodAdvice.LENGTHEN;
            p.reason = Reason.LOWER;
            p.chosenMs = within(Num.ceilPeriod(Math.max(lo, headroomMs(p))), lo, hi);
        } else if (p.execMs >= EXEC_NEAR_PERIOD_PCT / 100 * p.ratio * run
                && within(Num.ceilPeriod(headroomMs(p)), lo, hi) > run) {
            p.verdict = PeriodAdvice.LENGTHEN;
            p.reason = Reason.HEADROOM;
            p.chosenMs = within(Num.ceilPeriod(headroomMs(p)), lo, hi);
        } else if (p.stalePct() >= MOSTLY_STALE_PCT && Num.floorPeriod(hi) >= run * MIN_SLOWDOWN) {
            p.verdict = PeriodAdvice.LENGTHEN;
            p.reason = Reason.STALE;
            p.chosenMs = Num.floorPeriod(hi);
        } else {
            p.verdict = PeriodAdvice.KEEP;
            p.chosenMs = run;
        }
        p.held = inflated && p.reason != Reason.STALE && (p.chosenMs > run || Double.isInfinite(lo));
        if (p.held) {
            p.chosenMs = run;
        }
    }

    /** @return the period that puts the p99 execution time at {@value #TARGET_EXEC_PCT}% of the deadline, ms */
    private static double headroomMs(Plan p) {
        return p.execMs / p.ratio / (TARGET_EXEC_PCT / 100);
    }

    /** @return {@code ms} moved into {@code [lo, hi]}: the rounded value where it fits, else the bound itself */
    private static double within(double ms, double lo, double hi) {
        if (ms > hi) {
            double down = Num.floorPeriod(hi);
            return down >= lo ? down : hi;
        }
        return Math.max(ms, lo);
    }

    private static PeriodBound tightest(List<PeriodBound> bounds) {
        PeriodBound tightest = null;
        for (PeriodBound b : bounds) {
            if (tightest == null || b.lower() && b.ms() > tightest.ms() || !b.lower() && b.ms() < tightest.ms()) {
                tightest = b;
            }
        }
        return tightest;
    }

    /** @return the commit rate of a key at its producer's chosen period, Hz (the measured rate, scaled) */
    private static double commitRateAtChosen(DataReport d, Map<String, Plan> byName) {
        Plan producer = byName.get(d.producer());
        return producer == null ? d.rateHz() : d.rateHz() * producer.periodMs / producer.chosenMs;
    }

    /**
     * The rate at which a key's value can change, Hz, for the sampling rule: its commit rate at
     * its producer's chosen period, but no more than the fastest of the producer's own inputs
     * changes, when it has inputs: a task that commits faster than its inputs change commits the
     * same information again (a chain of 1 ms tasks would otherwise ask each consumer to run twice
     * as fast as the one before it). A producer without inputs (a sensor, a source of its own)
     * counts by its commits.
     */
    private static double rateAtChosen(DataReport d, Map<String, Plan> byName) {
        return rateAtChosen(d, byName, new HashSet<>());
    }

    private static double rateAtChosen(DataReport d, Map<String, Plan> byName, Set<String> visiting) {
        double commits = commitRateAtChosen(d, byName);
        Plan producer = byName.get(d.producer());
        if (producer == null || producer.inputs.isEmpty() || !visiting.add(d.name())) {
            return commits; // no inputs, or a cycle of data: by commits
        }
        double fastestInput = 0;
        for (DataReport input : producer.inputs) {
            if (input.rateHz() > 0) {
                fastestInput = Math.max(fastestInput, rateAtChosen(input, byName, visiting));
            }
        }
        visiting.remove(d.name());
        return fastestInput > 0 ? Math.min(commits, fastestInput) : commits;
    }

    private static List<PeriodBound> upperBounds(Plan p, Report report, Map<String, Plan> byName) {
        List<PeriodBound> bounds = new ArrayList<>();
        for (DataReport d : p.inputs) {
            if (d.rateHz() <= 0) {
                continue;
            }
            double commits = commitRateAtChosen(d, byName);
            double rate = rateAtChosen(d, byName);
            boolean scaled = commits != d.rateHz();
            boolean capped = rate < commits;
            Map<String, Object> evidence = new LinkedHashMap<>();
            evidence.put("input", d.name());
            evidence.put("producer", d.producer());
            evidence.put("input_rate_hz", d.rateHz());
            if (scaled) {
                evidence.put("input_rate_at_suggested_hz", Num.round2(commits));
            }
            if (capped) {
                evidence.put("input_change_rate_hz", Num.round2(rate));
            }
            String why = capped ? ": '" + d.producer() + "' commits faster than its inputs change"
                    : scaled ? " at '" + d.producer() + "''s suggested period" : "";
            bounds.add(new PeriodBound(PeriodBound.SAMPLING, PeriodBound.UPPER, Num.round3(samplingBoundMs(rate)),
                    String.format(Locale.ROOT, "sampling of '%s' (%s Hz%s)", d.name(), Num.num(Num.round2(rate)), why),
                    evidence));
        }
        ReactionConstraint r = p.task.reaction();
        if (r != null) {
            DataReport input = report.key(r.input());
            double measured = input == null ? 0.0 : input.rateHz();
            double rate = input == null ? 0.0 : rateAtChosen(input, byName);
            double ageMs = inputAgeP99Ms(r, rate);
            double boundMs = r.maxPeriodMs(ageMs);
            Map<String, Object> evidence = new LinkedHashMap<>();
            evidence.put("input", r.input());
            evidence.put("input_rate_hz", measured);
            evidence.put("input_delay_ms", Num.round3(r.inputDelayMs()));
            evidence.put("input_age_p99_ms", Num.round3(ageMs));
            evidence.put("speed_mps", r.speedMps());
            evidence.put("obstacle_speed_mps", r.obstacleSpeedMps());
            evidence.put("closing_speed_mps", r.closingSpeedMps());
            evidence.put("assumption", r.obstacleAssumption());
            evidence.put("stopping_distance_m", Num.round3(r.stoppingDistanceM()));
            evidence.put("range_m", r.rangeM());
            evidence.put("needed_m", Num.round3(r.closingSpeedMps() * (p.periodMs + ageMs) / 1000.0
                    + r.stoppingDistanceM()));
            evidence.put("max_safe_period_ms", Num.round3(boundMs));
            evidence.put("safe", boundMs > 0 && p.periodMs <= boundMs);
            bounds.add(new PeriodBound(PeriodBound.REACTION, PeriodBound.UPPER, Num.round3(boundMs),
                    String.format(Locale.ROOT, "reaction to '%s' (%s m in range at %s m/s, input age p99 %s)",
                            r.input(), Num.num(r.rangeM()), Num.num(r.closingSpeedMps()), Num.ms(Num.round3(ageMs))),
                    evidence));
        }
        for (DataReport d : p.outputs) {
            for (String consumer : d.consumers()) {
                Plan consuming = byName.get(consumer);
                TaskReport c = consuming != null ? consuming.task : report.task(consumer);
                Double maxAgeMs = c == null ? null : c.inputMaxAgeMs().get(d.name());
                if (maxAgeMs == null) {
                    continue;
                }
                Map<String, Object> evidence = new LinkedHashMap<>();
                evidence.put("key", d.name());
                evidence.put("consumer", consumer);
                evidence.put("max_age_ms", maxAgeMs);
                evidence.put("exec_p99_ms", Num.round3(p.execMs));
                bounds.add(new PeriodBound(PeriodBound.FRESHNESS, PeriodBound.UPPER, Num.round3(maxAgeMs - p.execMs),
                        String.format(Locale.ROOT, "freshness of '%s' for '%s' (max age %s)", d.name(), consumer,
                                Num.ms(maxAgeMs)), evidence));
            }
        }
        return bounds;
    }

    /** @return the highest-priority task the response-time test does not clear at the chosen periods, not in {@code stuck} */
    private static Plan firstFailing(List<Plan> plans, int cores, Set<Plan> stuck) {
        List<ScheduledTask> tasks = Schedulability.rateMonotonic(scheduled(plans));
        int n = tasks.size();
        long[] c = new long[n];
        long[] t = new long[n];
        long[] d = new long[n];
        for (int i = 0; i < n; i++) {
            c[i] = tasks.get(i).execP99Ns();
            t[i] = tasks.get(i).periodNs();
            d[i] = tasks.get(i).deadlineNs();
        }
        long[] r = Schedulability.responseTimes(c, t, d, cores);
        Map<String, Plan> byName = new HashMap<>();
        plans.forEach(p -> byName.put(p.name(), p));
        for (int i = 0; i < n; i++) {
            Plan p = byName.get(tasks.get(i).name());
            if (r[i] < 0 && !stuck.contains(p)) {
                return p;
            }
        }
        return null;
    }

    private static List<ScheduledTask> scheduled(List<Plan> plans) {
        List<ScheduledTask> tasks = new ArrayList<>();
        for (Plan p : plans) {
            tasks.add(Schedulability.of(p.task, p.chosenMs));
        }
        return tasks;
    }

    /**
     * The least period from which every longer one clears task f in the response-time test, the
     * other tasks at their chosen periods. A longer period is a lower rate-monotonic priority: the
     * tasks of shorter period (and, conservatively, of equal period) are above f. Between two of
     * their periods the set above f is fixed, so is f's response time R, and f clears every
     * period T there with {@code R <= ratio * T}; the search goes down from the longest segment.
     *
     * @return the bound in ms, or infinity when no period clears f
     */
    private static double responseLowerBoundMs(Plan f, List<Plan> plans, int cores) {
        List<Plan> others = new ArrayList<>(plans);
        others.remove(f);
        List<ScheduledTask> above = Schedulability.rateMonotonic(scheduled(others));
        int n = above.size();
        long[] c = new long[n + 1];
        long[] t = new long[n + 1];
        long[] d = new long[n];
        for (int i = 0; i < n; i++) {
            c[i] = above.get(i).execP99Ns();
            t[i] = above.get(i).periodNs();
            d[i] = above.get(i).deadlineNs();
        }
        long[] r = Arrays.copyOf(Schedulability.responseTimes(Arrays.copyOf(c, n), Arrays.copyOf(t, n), d, cores), n + 1);
        long execNs = Math.round(f.execMs * 1e6);
        long[] periods = Arrays.stream(t, 0, n).distinct().sorted().toArray();
        for (int j = periods.length - 1; j >= -1; j--) {
            long start = j < 0 ? 0 : periods[j];
            long end = j + 1 < periods.length ? periods[j + 1] : Long.MAX_VALUE;
            int count = 0;
            while (count < n && t[count] <= start) {
                count++;
            }
            long[] exec = Arrays.copyOf(c, count + 1);
            exec[count] = execNs;
            long response = Schedulability.responseNs(exec, t, r, count, cores, Schedulability.HORIZON_NS);
            if (response < 0) {
                return end == Long.MAX_VALUE ? Double.POSITIVE_INFINITY : end / 1e6;
            }
            long needNs = (long) Math.ceil(response / f.ratio);
            if (needNs >= end) {
                return end / 1e6;
            }
            if (needNs > start) {
                return needNs / 1e6;
            }
        }
        return 0;
    }

    private static PeriodAdvice finish(Plan p, TaskUtilization row, int cores, AdviceNote together, String machineWhy) {
        List<PeriodBound> bounds = new ArrayList<>();
        Map<String, Object> execEvidence = new LinkedHashMap<>();
        execEvidence.put("exec_p99_ms", Num.round3(p.execMs));
        execEvidence.put("exec_max_ms", Num.round3(p.task.execUs().max() / 1000.0));
        execEvidence.put("deadline_over_period", Num.round3(p.ratio));
        bounds.add(new PeriodBound(PeriodBound.EXEC, PeriodBound.LOWER, Num.round3(p.execLowerMs()),
                p.ratio == 1.0 ? "exec p99" : "exec p99 in a deadline of " + Num.num(Num.round3(p.ratio))
                        + " x the period", execEvidence));
        String onCores = cores + (cores == 1 ? " core" : " cores");
        if (p.responseLowerMs > 0) {
            Map<String, Object> evidence = new LinkedHashMap<>();
            evidence.put("cores", cores);
            evidence.put("test", Schedulability.testOnCores(cores));
            evidence.put("clears_at_every_period_from", Double.isInfinite(p.responseLowerMs) ? "none" : "this bound");
            bounds.add(new PeriodBound(PeriodBound.RESPONSE_TIME, PeriodBound.LOWER, Double.isInfinite(p.responseLowerMs)
                    ? Double.POSITIVE_INFINITY : Num.round3(p.responseLowerMs),
                    "response time in the set on " + onCores, evidence));
        } else if (row != null && row.responseP99MsOnCores() != null) {
            Map<String, Object> evidence = new LinkedHashMap<>();
            evidence.put("cores", cores);
            evidence.put("test", Schedulability.testOnCores(cores));
            evidence.put("response_p99_ms", Num.round3(row.responseP99MsOnCores()));
            bounds.add(new PeriodBound(PeriodBound.RESPONSE_TIME, PeriodBound.LOWER,
                    Num.round3(row.responseP99MsOnCores() / p.ratio), "response time in the set on " + onCores,
                    evidence));
        }
        bounds.addAll(p.upper);
        PeriodBound lower = null;
        for (PeriodBound b : bounds) {
            if (b.lower() && (lower == null || b.ms() > lower.ms())) {
                lower = b;
            }
        }
        PeriodBound upper = tightest(p.upper);
        List<AdviceNote> notes = new ArrayList<>();
        if (p.reason == Reason.STALE) {
            notes.add(staleNote(p, upper));
        }
        if (together != null) {
            notes.add(together);
        }
        List<String> resolve = p.verdict.equals(PeriodAdvice.INFEASIBLE) ? resolve(p, lower, upper, cores) : List.of();
        String verdict = p.held ? PeriodAdvice.MACHINE : p.verdict;
        return new PeriodAdvice(p.name(), p.periodMs, p.chosenMs, verdict, lower.ms(),
                upper == null ? null : upper.ms(), lower.label(), upper == null ? null : upper.label(), bounds, resolve,
                notes, message(p, lower, upper, resolve, machineWhy));
    }

    private static AdviceNote staleNote(Plan p, PeriodBound upper) {
        double execMeanMs = p.task.execUs().mean() / 1000.0;
        double freedMsPerS = execMeanMs * (1000.0 / p.periodMs - 1000.0 / p.chosenMs);
        Map<String, Object> evidence = new LinkedHashMap<>();
        evidence.put("stale_runs", p.task.staleRuns());
        evidence.put("runs", p.task.runs());
        evidence.put("stale_pct", Num.round2(p.stalePct()));
        evidence.put("exec_mean_ms", Num.round3(execMeanMs));
        evidence.put("slowdown_factor", Num.round2(p.chosenMs / p.periodMs));
        evidence.put("freed_cpu_ms_per_s", Num.round2(freedMsPerS));
        String limit = upper == null ? "no rule bounds it from above" : "up to " + upper.label();
        return new AdviceNote("mostly_stale", evidence, String.format(Locale.ROOT,
                "'%s' found no new data in %.0f%% of its runs; at %s (%.1fx slower, %s) it frees %s of CPU per"
                        + " second", p.name(), p.stalePct(), Num.ms(p.chosenMs), p.chosenMs / p.periodMs,
                limit, Num.ms(Num.round2(freedMsPerS))));
    }

    private static String bound(PeriodBound b) {
        return Num.ms(b.ms()) + " by " + b.label();
    }

    private static String message(Plan p, PeriodBound lower, PeriodBound upper, List<String> resolve,
                                  String machineWhy) {
        String name = "'" + p.name() + "'";
        String change = name + " " + Num.ms(p.periodMs) + " -> " + Num.ms(p.chosenMs) + ": ";
        String atMost = upper == null ? "" : "; at most " + bound(upper);
        if (p.held) {
            return String.format(Locale.ROOT, "%s keeps %s: the run's figures ask for at least %s, but the machine"
                            + " was %s, which inflates execution times; re-run on a quiet machine to tell the task's"
                            + " own cost", name, Num.ms(p.periodMs), bound(lower), machineWhy);
        }
        switch (p.verdict) {
            case PeriodAdvice.KEEP:
                String keep = name + " keeps " + Num.ms(p.periodMs) + ": at least " + bound(lower)
                        + (upper == null ? "; no rule bounds it from above" : atMost);
                if (upper != null && p.execMs >= EXEC_NEAR_PERIOD_PCT / 100 * p.ratio * p.periodMs) {
                    keep += String.format(Locale.ROOT, "; its exec p99 is %.0f%% of its deadline and %s allows no"
                                    + " longer period: less work (exec p99 at most %s) would leave it headroom",
                            100 * p.execMs / (p.ratio * p.periodMs), upper.label(),
                            Num.ms(Num.round3(TARGET_EXEC_PCT / 100 * p.ratio * p.periodMs)));
                }
                return keep;
            case PeriodAdvice.SHORTEN:
                return change + "at most " + bound(upper) + "; at least " + bound(lower);
            case PeriodAdvice.LENGTHEN:
                if (p.reason == Reason.STALE) {
                    return change + String.format(Locale.ROOT, "%.0f%% of its runs found no new data", p.stalePct())
                            + atMost + "; at least " + bound(lower);
                }
                if (p.reason == Reason.HEADROOM) {
                    return change + String.format(Locale.ROOT, "its exec p99 %s is %.0f%% of its deadline, no"
                                    + " headroom; the suggestion puts it at %.0f%% where the bounds allow (at least %s%s)",
                            Num.ms(Num.round3(p.execMs)), 100 * p.execMs / (p.ratio * p.periodMs), TARGET_EXEC_PCT,
                            bound(lower), atMost);
                }
                return change + "at least " + bound(lower) + atMost;
            default:
                if (Double.isInfinite(lower.ms())) {
                    return String.format(Locale.ROOT, "no period fits %s: the tasks above it leave it no time at any"
                            + " period; it keeps %s; to resolve: %s", name, Num.ms(p.periodMs), String.join("; ", resolve));
                }
                String upperText = upper.ms() <= 0 ? "and " + upper.label() + " allows none ("
                        + Num.ms(upper.ms()) + ")" : "at most " + bound(upper);
                return String.format(Locale.ROOT, "no period fits %s: at least %s, %s; suggested %s, the least it"
                                + " needs; to resolve: %s", name, bound(lower), upperText, Num.ms(p.chosenMs),
                        String.join("; ", resolve));
        }
    }

    /** @return what would open an empty interval: one way from each side of the collision */
    private static List<String> resolve(Plan p, PeriodBound lower, PeriodBound upper, int cores) {
        List<String> ways = new ArrayList<>();
        double hi = upper == null ? Double.POSITIVE_INFINITY : upper.ms();
        double lo = lower.ms();
        if (hi <= 0) {
            ways.add("no period satisfies " + upper.label() + " alone; what would:");
        } else if (lower.rule().equals(PeriodBound.EXEC)) {
            ways.add("less work: exec p99 at most " + Num.ms(Num.round3(hi * p.ratio)));
        } else {
            ways.add(String.format(Locale.ROOT, "another core (on %d the tasks above '%s' delay it), or less work in"
                    + " it or in them", cores, p.name()));
        }
        if (upper == null || Double.isInfinite(lo)) {
            return ways;
        }
        Map<String, Object> e = upper.evidence();
        switch (upper.rule()) {
            case PeriodBound.SAMPLING -> ways.add(String.format(Locale.ROOT, "an input that changes more slowly: '%s'"
                    + " at most %s Hz", e.get("input"), Num.num(Num.round2(1000.0 / (2 * lo)))));
            case PeriodBound.REACTION -> {
                ReactionConstraint r = p.task.reaction();
                double ageMs = ((Number) e.get("input_age_p99_ms")).doubleValue();
                double freshestMs = 1000.0 * (r.rangeM() - r.stoppingDistanceM()) / r.closingSpeedMps() - lo;
                double speed = (r.rangeM() - r.stoppingDistanceM()) * 1000.0 / (lo + ageMs) - r.obstacleSpeedMps();
                if (freshestMs > r.inputDelayMs()) {
                    ways.add(String.format(Locale.ROOT, "a faster input: '%s' at least %s Hz (age p99 at most %s, now %s)",
                            r.input(), Num.num(Num.round2(0.99 * 1000.0 / (freshestMs - r.inputDelayMs()))),
                            Num.ms(Num.round3(freshestMs)), Num.ms(Num.round3(ageMs))));
                }
                ways.add(speed > 0 ? String.format(Locale.ROOT, "a lower speed: at most %s m/s", Num.num(Num.round3(speed)))
                        : "a longer range or a shorter stopping distance (no speed would do at this input age)");
            }
            default -> ways.add(String.format(Locale.ROOT, "'%s' accepting '%s' up to %s old (now %s)",
                    e.get("consumer"), e.get("key"), Num.ms(Num.round3(lo + p.execMs)), Num.ms((Double) e.get("max_age_ms"))));
        }
        return ways;
    }

    /** @return per task named, the released_together note of its group */
    private static Map<String, AdviceNote> releasedTogether(Report report, boolean inflated, String machineWhy) {
        // Groups by period and by the phase of the first release within it, in nanoseconds (the
        // unit periods are declared in: any period of at least 1 ns has a phase).
        Map<String, List<TaskReport>> groups = new LinkedHashMap<>();
        for (TaskReport task : report.tasks()) {
            if (task.periodMs() == null || task.offsetMs() == null || task.latenessUs() == null) {
                continue; // a report without offsets or lateness (lateness_us is optional): no such note
            }
            long periodNs = Math.round(task.periodMs() * 1e6);
            if (periodNs <= 0) {
                continue;
            }
            groups.computeIfAbsent(periodNs + "/" + phaseNs(task.offsetMs(), periodNs), k -> new ArrayList<>()).add(task);
        }
        Map<String, AdviceNote> notes = new HashMap<>();
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
            double stepMs = Num.round3(period / group.size());
            Map<String, Object> evidence = new LinkedHashMap<>();
            evidence.put("tasks_released_together", group.size());
            evidence.put("offset_ms", Num.round3(offset));
            evidence.put("lateness_p99_median_ms", Num.round3(medianP99Ms));
            evidence.put("lateness_p99_median_pct_of_period", Num.round2(pct));
            evidence.put("first_task", first.name());
            evidence.put("first_lateness_p50_ms", Num.round3(first.latenessUs().p50() / 1000.0));
            evidence.put("latest_lateness_p50_ms", Num.round3(latest.latenessUs().p50() / 1000.0));
            evidence.put("suggested_offset_step_ms", stepMs);
            String message = inflated ? String.format(Locale.ROOT, "'%s' and %d other tasks of period %s are released"
                            + " at the same instant, but the machine was %s, which inflates lateness: no advice on"
                            + " their offsets from this run", latest.name(), group.size() - 1, Num.ms(period), machineWhy)
                    : String.format(Locale.ROOT,
                            "'%s' and %d other tasks of period %s are released at the same instant (offset %s) and"
                                    + " wait for each other: lateness p99 %s (median over them, %.0f%% of the period),"
                                    + " p50 from %s ('%s') to %s ('%s'); spread their offsets over the period"
                                    + " (Schedule.periodic(period, offset, deadline)), e.g. %s apart",
                            latest.name(), group.size() - 1, Num.ms(period), Num.ms(Num.round3(offset)),
                            Num.ms(Num.round3(medianP99Ms)), pct, Num.ms(Num.round3(first.latenessUs().p50() / 1000.0)),
                            first.name(), Num.ms(Num.round3(latest.latenessUs().p50() / 1000.0)), latest.name(),
                            Num.ms(stepMs));
            notes.put(latest.name(), new AdviceNote("released_together", evidence, message));
        }
        return notes;
    }

    /** @return where within a period of {@code periodNs} (at least 1) an offset falls, in ns */
    private static long phaseNs(double offsetMs, long periodNs) {
        return Math.floorMod(Math.round(offsetMs * 1e6), periodNs);
    }
}
