package io.rtaware.core.analysis;

import io.rtaware.core.report.Report;
import io.rtaware.core.report.Rounding;
import io.rtaware.core.report.TaskReport;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Schedulability of a set of periodic tasks under rate-monotonic (RM) fixed priorities, from
 * their measured execution times (the p99 and the max as C):
 * <ul>
 *   <li>utilization per task, {@code C / T};</li>
 *   <li>the Liu and Layland bound {@code n (2^(1/n) - 1)}: total utilization at or below it is
 *   enough for RM on one core (a sufficient, not a necessary, test);</li>
 *   <li>on one core, the exact response-time analysis: the worst-case response time of task k
 *   is the smallest fixed point of {@code R = C_k + sum_{i in hp(k)} ceil(R / T_i) C_i}, hp(k)
 *   being the tasks of shorter period (ties broken by deadline, then by the order given); task k
 *   meets its deadline if {@code R <= D_k};</li>
 *   <li>on the m cores the tasks may use (m &gt; 1), the response-time bound for global
 *   fixed-priority scheduling of Bertogna and Cirinei (RTSS 2007): {@code R = C_k + floor(
 *   sum_{i in hp(k)} min(W_i(R), R - C_k + 1) / m)}, with the workload of a higher-priority task
 *   in a window of length L {@code W_i(L) = N C_i + min(C_i, L + R_i - C_i - N T_i)},
 *   {@code N = floor((L + R_i - C_i) / T_i)}. This test is <b>sufficient only</b>: a task it
 *   clears meets its deadline whatever the interleaving, a task it does not clear may still
 *   meet it (no exact test is known that is cheap for global scheduling). A higher-priority task
 *   it does not clear enters as one core taken whole (its cycles never overlap: rtaware skips
 *   the releases that fall while one runs, so one task takes at most one core). It models threads that may run on any of the m cores (the
 *   threads of rtaware's executors are not pinned) under fixed priorities (what
 *   {@code rtaware-rt} gives with SCHED_FIFO); under the operating system's default time
 *   sharing it is a model, not a guarantee. Partitioned scheduling (each task pinned to one
 *   core) is not what the executors do and is not analyzed;</li>
 *   <li>utilization per core (above 1 nothing can fit).</li>
 * </ul>
 * Continuous and once tasks have no period and are listed as excluded: their work is not in
 * the analysis. Stateless and thread-safe.
 */
public final class Schedulability {

    /** The longest response time followed where no deadline limits it (the advice's search): a day, in ns. */
    static final long HORIZON_NS = 86_400_000_000_000L;
    /** The most fixed-point steps one response time takes before it counts as unbounded. */
    static final int MAX_ITERATIONS = 1_000_000;

    private Schedulability() {
    }

    /**
     * @param report a finished run
     * @param cores the cores the tasks may use, at least 1
     * @return the analysis of the run's periodic tasks at their periods
     */
    public static SchedulabilityReport analyze(Report report, int cores) {
        return analyze(report, Map.of(), cores);
    }

    /**
     * @param report a finished run
     * @param periodsMs periods to analyze tasks at instead of the run's, ms, by task name (each
     *     deadline keeps its ratio to the period); tasks not named keep the run's
     * @param cores the cores the tasks may use, at least 1
     * @return the analysis of the run's periodic tasks at those periods
     */
    public static SchedulabilityReport analyze(Report report, Map<String, Double> periodsMs, int cores) {
        List<ScheduledTask> periodic = new ArrayList<>();
        List<String> excluded = new ArrayList<>();
        for (TaskReport t : report.tasks()) {
            if (t.periodMs() != null && t.periodMs() > 0) {
                periodic.add(of(t, periodsMs.getOrDefault(t.name(), t.periodMs())));
            } else {
                excluded.add(t.name());
            }
        }
        return analyze(periodic, excluded, cores);
    }

    /**
     * @param task a periodic task of a report
     * @param periodMs the period to analyze it at, ms (its deadline keeps its ratio to the period)
     * @return the task as the analysis sees it
     */
    static ScheduledTask of(TaskReport task, double periodMs) {
        double ratio = task.deadlineMs() == null ? 1.0 : task.deadlineMs() / task.periodMs();
        long periodNs = Math.max(1, Math.round(periodMs * 1e6));
        return new ScheduledTask(task.name(), periodNs, Math.max(1, Math.round(periodMs * ratio * 1e6)),
                Math.round(task.execUs().p99() * 1e3), Math.round(task.execUs().max() * 1e3));
    }

    /**
     * @param tasks the periodic tasks, in any order
     * @param excluded names of the tasks without a period
     * @param cores the cores the tasks may use, at least 1
     * @return the analysis
     */
    public static SchedulabilityReport analyze(List<ScheduledTask> tasks, List<String> excluded, int cores) {
        if (cores < 1) {
            throw new IllegalArgumentException("cores must be at least 1, got " + cores);
        }
        List<ScheduledTask> ordered = rateMonotonic(tasks);
        int n = ordered.size();
        long[] periodNs = new long[n];
        long[] deadlineNs = new long[n];
        long[] p99Ns = new long[n];
        long[] maxNs = new long[n];
        for (int i = 0; i < n; i++) {
            ScheduledTask t = ordered.get(i);
            periodNs[i] = t.periodNs();
            deadlineNs[i] = t.deadlineNs();
            p99Ns[i] = t.execP99Ns();
            maxNs[i] = t.execMaxNs();
        }
        long[] rP99 = responseTimes(p99Ns, periodNs, deadlineNs);
        long[] rMax = responseTimes(maxNs, periodNs, deadlineNs);
        long[] rCores = responseTimes(p99Ns, periodNs, deadlineNs, cores);
        List<TaskUtilization> rows = new ArrayList<>();
        double uP99 = 0;
        double uMax = 0;
        boolean allP99 = true;
        boolean allMax = true;
        boolean allCores = true;
        String firstFailure = null;
        String firstFailureCores = null;
        for (int i = 0; i < n; i++) {
            ScheduledTask t = ordered.get(i);
            double u99 = (double) p99Ns[i] / periodNs[i];
            double uMx = (double) maxNs[i] / periodNs[i];
            uP99 += u99;
            uMax += uMx;
            boolean ok99 = rP99[i] >= 0;
            boolean okMax = rMax[i] >= 0;
            boolean okCores = rCores[i] >= 0;
            allP99 &= ok99;
            allMax &= okMax;
            allCores &= okCores;
            if (!ok99 && firstFailure == null) {
                firstFailure = t.name();
            }
            if (!okCores && firstFailureCores == null) {
                firstFailureCores = t.name();
            }
            rows.add(new TaskUtilization(t.name(), i + 1, periodNs[i] / 1e6, deadlineNs[i] / 1e6, p99Ns[i] / 1e6,
                    maxNs[i] / 1e6, round4(u99), round4(uMx), ok99 ? rP99[i] / 1e6 : null,
                    okMax ? rMax[i] / 1e6 : null, ok99, okMax, okCores ? rCores[i] / 1e6 : null, okCores));
        }
        double bound = liuLaylandBound(n);
        boolean llHolds = uP99 <= bound;
        return new SchedulabilityReport(cores, rows, excluded, round4(uP99), round4(uMax), round4(bound), llHolds,
                allP99, allMax, round4(uP99 / cores), round4(uMax / cores), allCores, testOnCores(cores),
                verdict(n, cores, uP99, llHolds, allP99, allMax, firstFailure, allCores, firstFailureCores));
    }

    /**
     * @param tasks periodic tasks
     * @return them in rate-monotonic priority order: shorter period first, then shorter deadline,
     *     then the order given
     */
    static List<ScheduledTask> rateMonotonic(List<ScheduledTask> tasks) {
        List<ScheduledTask> ordered = new ArrayList<>(tasks);
        // List.sort is stable: equal periods and deadlines keep the order given.
        ordered.sort(Comparator.comparingLong(ScheduledTask::periodNs).thenComparingLong(ScheduledTask::deadlineNs));
        return ordered;
    }

    /**
     * @param cores the cores the tasks may use
     * @return the name of the response-time test used on that many cores
     */
    public static String testOnCores(int cores) {
        return cores == 1 ? "exact response-time analysis, one core"
                : "global fixed-priority response-time bound (Bertogna and Cirinei), sufficient only";
    }

    /**
     * @param n number of tasks
     * @return the Liu and Layland utilization bound {@code n (2^(1/n) - 1)}; 1 for n = 0
     */
    public static double liuLaylandBound(int n) {
        return n == 0 ? 1.0 : n * (Math.pow(2.0, 1.0 / n) - 1.0);
    }

    /**
     * Exact response-time analysis on one core, tasks given in priority order (index 0 highest).
     *
     * @param execNs worst-case execution time C of each task
     * @param periodNs period T of each task
     * @param deadlineNs relative deadline D of each task
     * @return the worst-case response time R of each task, or -1 where the iteration passes the
     *     deadline (the task can miss)
     */
    public static long[] responseTimes(long[] execNs, long[] periodNs, long[] deadlineNs) {
        return responseTimes(execNs, periodNs, deadlineNs, 1);
    }

    /**
     * Response-time analysis on {@code cores} cores, tasks given in priority order (index 0
     * highest): exact on one core, the global bound of Bertogna and Cirinei (sufficient only) on
     * more, where a task above that passes its own deadline counts as one core taken whole.
     *
     * @param execNs worst-case execution time C of each task
     * @param periodNs period T of each task
     * @param deadlineNs relative deadline D of each task
     * @param cores the cores, at least 1
     * @return the response time (bound) R of each task, or -1 where it passes the deadline
     */
    public static long[] responseTimes(long[] execNs, long[] periodNs, long[] deadlineNs, int cores) {
        int n = execNs.length;
        long[] response = new long[n];
        for (int k = 0; k < n; k++) {
            response[k] = responseNs(execNs, periodNs, response, k, cores, deadlineNs[k]);
        }
        return response;
    }

    /**
     * The response time of task k (priority order) given the tasks above it, by fixed-point
     * iteration from {@code C_k}; at most {@value #MAX_ITERATIONS} steps.
     *
     * @param execNs C of each task
     * @param periodNs T of each task
     * @param responseNs R of each task above k, -1 for one past its deadline (read on more than one core only)
     * @param k the task
     * @param cores the cores
     * @param limitNs the longest response time of interest
     * @return the smallest fixed point, or -1 if it passes {@code limitNs}, the tasks above use
     *     every core, or the iteration does not settle in time (which only a utilization within a
     *     hair of the cores' can cause)
     */
    static long responseNs(long[] execNs, long[] periodNs, long[] responseNs, int k, int cores, long limitNs) {
        double above = 0;
        for (int i = 0; i < k; i++) {
            // One task occupies at most one core at a time (its cycles never overlap).
            double u = (double) execNs[i] / periodNs[i];
            above += cores == 1 ? u : responseNs[i] < 0 ? 1.0 : Math.min(1.0, u);
        }
        if (above >= cores) {
            return -1; // the tasks above fill every core: the response time has no bound
        }
        long c = execNs[k];
        long r = c;
        for (int step = 0; step < MAX_ITERATIONS && r <= limitNs; step++) {
            long next;
            if (cores == 1) {
                next = c;
                for (int i = 0; i < k && next <= limitNs; i++) {
                    next = addSat(next, mulSat(ceilDiv(r, periodNs[i]), execNs[i]));
                }
            } else {
                long interference = 0;
                int capped = 0;
                for (int i = 0; i < k; i++) {
                    long workload = responseNs[i] < 0 ? Long.MAX_VALUE // passes its deadline: a core taken whole
                            : workloadNs(execNs[i], periodNs[i], responseNs[i], r);
                    if (workload >= r - c + 1) {
                        interference = addSat(interference, r - c + 1);
                        capped++;
                    } else {
                        interference = addSat(interference, workload);
                    }
                }
                next = addSat(c, interference / cores);
                if (capped >= cores && next != r) {
                    // While at least m terms are capped at R - C + 1, every R has f(R) > R: no fixed
                    // point before the first capped term falls below its cap, so go there at once
                    // (at 1 ns a step the climb would take millions of steps). Tasks of equal
                    // parameters fall below at the same window: a run of them is searched once.
                    long first = Long.MAX_VALUE;
                    long[] last = null; // {C, T, R, window}: the search before, reused by a task of equal parameters
                    for (int i = 0; i < k; i++) {
                        long e = execNs[i];
                        long p = periodNs[i];
                        long q = responseNs[i];
                        if (q < 0) {
                            continue; // a core taken whole stays capped
                        }
                        if (workloadNs(e, p, q, r) >= r - c + 1) {
                            if (last == null || last[0] != e || last[1] != p || last[2] != q) {
                                last = new long[] {e, p, q, belowCapNs(e, p, q, c, r)};
                            }
                            first = Math.min(first, last[3]);
                        }
                    }
                    next = Math.max(next, first);
                }
            }
            if (next == r) {
                return r;
            }
            r = next;
        }
        return -1;
    }

    /**
     * The most work a higher-priority task can do in a window of length {@code windowNs} under
     * global scheduling (Bertogna and Cirinei): its jobs packed as densely as its period and its
     * response time allow.
     */
    private static long workloadNs(long execNs, long periodNs, long responseNs, long windowNs) {
        long reach = windowNs + responseNs - execNs;
        long jobs = Math.floorDiv(reach, periodNs);
        return addSat(mulSat(jobs, execNs), Math.min(execNs, reach - jobs * periodNs));
    }

    /** @return {@code a * b} for non-negative a and b, or {@link Long#MAX_VALUE} where it would overflow */
    private static long mulSat(long a, long b) {
        return b != 0 && a > Long.MAX_VALUE / b ? Long.MAX_VALUE : a * b;
    }

    /** @return {@code a + b} for non-negative a and b, or {@link Long#MAX_VALUE} where it would overflow */
    private static long addSat(long a, long b) {
        return a > Long.MAX_VALUE - b ? Long.MAX_VALUE : a + b;
    }

    /**
     * @return the least window longer than {@code fromNs} in which the task's workload falls below
     *     {@code window - c + 1} (it grows at most as fast as the window, so it stays below after),
     *     or {@link #HORIZON_NS} + 1 if none does before the horizon
     */
    private static long belowCapNs(long execNs, long periodNs, long responseNs, long c, long fromNs) {
        long lo = fromNs;
        long hi = HORIZON_NS + 1;
        while (hi - lo > 1) {
            long mid = lo + (hi - lo) / 2;
            if (workloadNs(execNs, periodNs, responseNs, mid) < mid - c + 1) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return hi;
    }

    private static long ceilDiv(long a, long b) {
        return -Math.floorDiv(-a, b);
    }

    private static String verdict(int n, int cores, double uP99, boolean llHolds, boolean rtaP99, boolean rtaMax,
                                  String firstFailure, boolean rtaCores, String firstFailureCores) {
        if (n == 0) {
            return "no periodic tasks to analyze";
        }
        StringBuilder sb = new StringBuilder();
        if (cores > 1) {
            if (rtaCores) {
                sb.append(String.format(Locale.ROOT, "schedulable on %d cores under global rate-monotonic priorities"
                        + " (response-time bound of Bertogna and Cirinei, p99 exec)", cores));
            } else {
                sb.append(String.format(Locale.ROOT, "not guaranteed on %d cores under global rate-monotonic"
                        + " priorities: '%s' may miss its deadline (response-time bound of Bertogna and Cirinei,"
                        + " p99 exec; sufficient only: it may also meet it)", cores, firstFailureCores));
            }
            sb.append("; ");
        }
        if (rtaP99) {
            sb.append("schedulable on one core under rate-monotonic priorities (exact RTA, p99 exec")
                    .append(rtaMax ? " and max exec)" : "; not with max exec)");
            if (!llHolds) {
                sb.append(", although above the Liu-Layland bound");
            }
        } else {
            sb.append("not schedulable on one core under rate-monotonic priorities: '").append(firstFailure)
                    .append("' can miss its deadline (exact RTA, p99 exec)");
        }
        double perCore = uP99 / cores;
        sb.append(String.format(Locale.ROOT, "; %.1f%% per core on %d core%s", 100 * perCore, cores,
                cores == 1 ? "" : "s"));
        if (perCore > 1) {
            sb.append(String.format(Locale.ROOT, ": overloaded, needs at least %d cores",
                    (int) Math.ceil(uP99 - 1e-9)));
        }
        return sb.toString();
    }

    private static double round4(double v) {
        return Rounding.toDecimals(v, 4);
    }
}
