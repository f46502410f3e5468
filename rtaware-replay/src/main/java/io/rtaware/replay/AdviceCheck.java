package io.rtaware.replay;

import io.rtaware.core.analysis.Advice;
import io.rtaware.core.analysis.PeriodAdvice;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Durations;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;

/**
 * Period advice checked against a recording by what-if replays ({@link WhatIfReplay}): the
 * recording replayed with the recorded periods (before), then with each suggested change added
 * in turn, in report order. A change whose replay is worse than the replay before it is
 * withdrawn ({@link PeriodAdvice#withdrawn}) with the figures that show it, and the advice is
 * made again with that task at its period (so no other suggestion rests on the withdrawn
 * change); the changes kept make the after. Worse means, over the advised tasks: more
 * misses of them all together, or of the changed task itself (percent of releases, to two
 * decimals, as the report rounds them), or more expired reads. Stale runs are printed but do not
 * judge: a task run at twice the rate of its input is stale in half its runs by design.
 * Changes are tried one at a time in report order and kept greedily.
 *
 * <p>What a what-if replay is, and is not: open loop (the robot's path is the recorded one), one
 * core (the step executor runs one cycle at a time), each cycle charged its task's recorded
 * execution times. A change is judged against the same replay without it, so both sides share
 * those limits; advice made for more cores than one may look worse here than it would run.
 * Stateless.
 */
public final class AdviceCheck {

    private AdviceCheck() {
    }

    /** The controller whose tasks a replay runs. */
    @FunctionalInterface
    public interface Controller {
        /**
         * @param periodsNs periods to run tasks at, by task name; tasks not named keep the
         *     recorded periods
         * @return a fresh set of the controller's tasks with those periods
         */
        List<TaskSpec> tasks(Map<String, Long> periodsNs);
    }

    /**
     * One suggested change as the replays judged it.
     *
     * @param task the task
     * @param fromMs its period before, ms
     * @param toMs the suggested period, ms
     * @param kept true if the change is kept
     * @param missPctBefore the advised tasks' misses in percent of their releases, in the replay before the change
     * @param missPctAfter the same with the change
     * @param reason why it was withdrawn, or "" when kept
     */
    public record Step(String task, double fromMs, double toMs, boolean kept, double missPctBefore,
                       double missPctAfter, String reason) {
    }

    /**
     * The outcome of a check.
     *
     * @param before the replay with the recorded periods
     * @param after the replay with every kept change (the before when none is)
     * @param steps each suggested change, in the order tried
     * @param advice the advice as finally made, the withdrawn changes withdrawn
     */
    public record Result(Report before, Report after, List<Step> steps, Advice advice) {

        /**
         * Copies the steps.
         *
         * @param before the replay with the recorded periods
         * @param after the replay with every kept change
         * @param steps each suggested change
         * @param advice the advice with the withdrawn changes withdrawn
         */
        public Result {
            steps = List.copyOf(steps);
        }
    }

    /**
     * @param recording the recording
     * @param controller the controller the recording was made with
     * @param periodsNs periods by task name; tasks not named keep the recorded periods
     * @return the report of a what-if replay with those periods
     * @throws IOException if the recording lacks a key the controller reads, or a value is malformed
     */
    public static Report replay(Recording recording, Controller controller, Map<String, Long> periodsNs)
            throws IOException {
        return WhatIfReplay.replay(recording, controller.tasks(periodsNs), controller.tasks(periodsNs)).report();
    }

    /**
     * Checks the advice by replays, and makes it again while a replay withdraws a change: the
     * withdrawn tasks keep their period and the others are advised around it, then checked again
     * (replays already made are not made again).
     *
     * @param recording the recording
     * @param controller the controller the recording was made with
     * @param settable the tasks whose period the controller can be given; a change of another is withdrawn
     * @param before the replay with the recorded periods ({@link #replay} with no periods)
     * @param advisor makes the advice, given the items withdrawn so far by task (e.g.
     *     {@code w -> PeriodAdvisor.advise(run, cores, machine, w)})
     * @return the check
     * @throws IOException as {@link #replay}
     */
    public static Result verify(Recording recording, Controller controller, Set<String> settable, Report before,
                                Function<Map<String, PeriodAdvice>, Advice> advisor) throws IOException {
        Map<String, PeriodAdvice> withdrawn = new LinkedHashMap<>();
        Map<String, Step> withdrawnSteps = new LinkedHashMap<>();
        Map<Map<String, Long>, Report> replays = new HashMap<>();
        replays.put(Map.of(), before);
        while (true) {
            Advice advice = advisor.apply(withdrawn);
            List<String> advised = advice.tasks().stream().map(PeriodAdvice::task).toList();
            Map<String, Long> kept = new LinkedHashMap<>();
            Map<String, Step> keptSteps = new LinkedHashMap<>();
            Report current = before;
            boolean more = false;
            for (PeriodAdvice a : advice.tasks()) {
                if (!a.changesPeriod()) {
                    continue;
                }
                double all = missPct(current, advised);
                String reason;
                Report candidate = current;
                Map<String, Long> trial = new LinkedHashMap<>(kept);
                trial.put(a.task(), Math.round(a.suggestedPeriodMs() * 1e6));
                if (settable.contains(a.task())) {
                    candidate = replays.get(trial);
                    if (candidate == null) {
                        candidate = replay(recording, controller, trial);
                        replays.put(trial, candidate);
                    }
                    reason = worse(current, candidate, a.task(), advised);
                } else {
                    reason = "a what-if replay cannot give '" + a.task() + "' a period";
                }
                Step step = new Step(a.task(), a.periodMs(), a.suggestedPeriodMs(), reason == null, all,
                        missPct(candidate, advised), reason == null ? "" : reason);
                if (reason == null) {
                    kept = trial;
                    current = candidate;
                    keptSteps.put(a.task(), step);
                } else {
                    withdrawn.put(a.task(), a.withdrawn(reason));
                    withdrawnSteps.put(a.task(), step);
                    more = true;
                    break; // the advice is made again without this change before the next is judged
                }
            }
            if (!more) {
                List<Step> steps = new ArrayList<>();
                for (String task : advised) {
                    Step step = withdrawnSteps.containsKey(task) ? withdrawnSteps.get(task) : keptSteps.get(task);
                    if (step != null) {
                        steps.add(step);
                    }
                }
                return new Result(before, current, steps, advice);
            }
        }
    }

    /** @return why {@code candidate} is worse than {@code current}, with the figures, or null if it is not */
    static String worse(Report current, Report candidate, String task, List<String> advised) {
        double allBefore = missPct(current, advised);
        double allAfter = missPct(candidate, advised);
        if (allAfter > allBefore) {
            return String.format(Locale.ROOT, "a what-if replay shows more misses: %s%% -> %s%% of the advised tasks'"
                    + " releases", pct(allBefore), pct(allAfter));
        }
        TaskReport own = current.task(task);
        TaskReport ownAfter = candidate.task(task);
        if (own != null && ownAfter != null && ownAfter.missPct() > own.missPct()) {
            return String.format(Locale.ROOT, "a what-if replay shows more misses of '%s': %s%% -> %s%% of its releases",
                    task, pct(own.missPct()), pct(ownAfter.missPct()));
        }
        long expiredBefore = sum(current, advised, TaskReport::expiredReads);
        long expiredAfter = sum(candidate, advised, TaskReport::expiredReads);
        if (expiredAfter > expiredBefore) {
            return String.format(Locale.ROOT, "a what-if replay shows more expired reads: %d -> %d", expiredBefore,
                    expiredAfter);
        }
        return null;
    }

    /** @return the advised tasks' misses in percent of their releases, to two decimals */
    static double missPct(Report report, List<String> advised) {
        long releases = sum(report, advised, TaskReport::releases);
        long misses = sum(report, advised, TaskReport::misses);
        return releases == 0 ? 0.0 : Math.round(10_000.0 * misses / releases) / 100.0;
    }

    private static long sum(Report report, List<String> advised, java.util.function.ToLongFunction<TaskReport> f) {
        long sum = 0;
        for (String name : advised) {
            TaskReport t = report.task(name);
            if (t != null) {
                sum += f.applyAsLong(t);
            }
        }
        return sum;
    }

    /**
     * @param result a check
     * @param file the recording, for the heading
     * @return each change as judged, then the advised tasks before and after side by side
     */
    public static String text(Result result, String file) {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "replay check of %s: what-if replays with the"
                + " recorded periods, then each suggested change in turn (open loop; one core; each cycle charged its"
                + " task's recorded execution times):%n", file));
        if (result.steps().isEmpty()) {
            sb.append("  no change suggested: nothing to replay\n");
        }
        for (Step s : result.steps()) {
            sb.append(String.format(Locale.ROOT, "  %-12s %8s -> %-8s %s%n", s.task(), Durations.formatMillis(s.fromMs()),
                    Durations.formatMillis(s.toMs()), s.kept() ? String.format(Locale.ROOT,
                            "kept: misses %s%% -> %s%% of the advised tasks' releases", pct(s.missPctBefore()),
                            pct(s.missPctAfter())) : "withdrawn: " + s.reason()));
        }
        List<String> advised = result.advice().tasks().stream().map(PeriodAdvice::task).toList();
        sb.append(String.format(Locale.ROOT, "%nbefore -> after (recorded periods -> the kept ones), replayed:%n"));
        sb.append(String.format(Locale.ROOT, "  %-12s %-18s %-17s %-15s %-17s %-15s %-17s %s%n", "task", "period",
                "releases", "misses", "miss%", "skipped", "stale runs", "expired reads"));
        for (String name : advised) {
            TaskReport b = result.before().task(name);
            TaskReport a = result.after().task(name);
            if (b == null || a == null) {
                continue;
            }
            sb.append(String.format(Locale.ROOT, "  %-12s %-18s %-17s %-15s %-17s %-15s %-17s %s%n", name,
                    Durations.formatMillis(b.periodMs()) + " -> " + Durations.formatMillis(a.periodMs()),
                    b.releases() + " -> " + a.releases(), b.misses() + " -> " + a.misses(),
                    pct(b.missPct()) + " -> " + pct(a.missPct()), b.skipped() + " -> " + a.skipped(),
                    b.staleRuns() + " -> " + a.staleRuns(), b.expiredReads() + " -> " + a.expiredReads()));
        }
        sb.append(String.format(Locale.ROOT, "  %-12s %-18s %-17s %-15s %s%n", "all advised", "",
                sum(result.before(), advised, TaskReport::releases) + " -> " + sum(result.after(), advised, TaskReport::releases),
                sum(result.before(), advised, TaskReport::misses) + " -> " + sum(result.after(), advised, TaskReport::misses),
                pct(missPct(result.before(), advised)) + " -> " + pct(missPct(result.after(), advised))));
        return sb.toString();
    }

    private static String pct(double v) {
        return String.format(Locale.ROOT, "%.2f", v);
    }
}
