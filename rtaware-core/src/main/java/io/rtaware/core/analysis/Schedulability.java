package io.rtaware.core.analysis;

import io.rtaware.core.report.Report;
import io.rtaware.core.report.Rounding;
import io.rtaware.core.report.TaskReport;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * Schedulability of a run's periodic tasks under rate-monotonic (RM) priorities, from their
 * measured execution times:
 * <ul>
 *   <li>utilization per task, {@code C / T}, with C the p99 and the max execution time;</li>
 *   <li>the Liu and Layland bound {@code n (2^(1/n) - 1)}: total utilization at or below it is
 *   enough for RM on one core (a sufficient, not a necessary, test);</li>
 *   <li>the exact response-time analysis for RM on one core: the worst-case response time of
 *   task i is the smallest fixed point of {@code R = C_i + sum_{j in hp(i)} ceil(R / T_j) C_j},
 *   hp(i) being the tasks of shorter period (ties broken by deadline, then report order); task i
 *   meets its deadline if {@code R <= D_i};</li>
 *   <li>utilization per core for the machine's core count (above 1 nothing can fit).</li>
 * </ul>
 * Continuous and once tasks have no period and are listed as excluded. Stateless and
 * thread-safe.
 */
public final class Schedulability {

    private Schedulability() {
    }

    /**
     * @param report a finished run
     * @param cores the machine's core count, at least 1
     * @return the analysis
     */
    public static SchedulabilityReport analyze(Report report, int cores) {
        if (cores < 1) {
            throw new IllegalArgumentException("cores must be at least 1, got " + cores);
        }
        List<TaskReport> periodic = new ArrayList<>();
        List<String> excluded = new ArrayList<>();
        for (TaskReport t : report.tasks()) {
            if (t.periodMs() != null && t.periodMs() > 0) {
                periodic.add(t);
            } else {
                excluded.add(t.name());
            }
        }
        // List.sort is stable: equal periods and deadlines keep report order.
        periodic.sort(Comparator.comparingDouble(TaskReport::periodMs)
                .thenComparingDouble(t -> t.deadlineMs() == null ? t.periodMs() : t.deadlineMs()));
        int n = periodic.size();
        long[] periodNs = new long[n];
        long[] deadlineNs = new long[n];
        long[] p99Ns = new long[n];
        long[] maxNs = new long[n];
        for (int i = 0; i < n; i++) {
            TaskReport t = periodic.get(i);
            periodNs[i] = Math.round(t.periodMs() * 1e6);
            deadlineNs[i] = Math.round((t.deadlineMs() == null ? t.periodMs() : t.deadlineMs()) * 1e6);
            p99Ns[i] = Math.round(t.execUs().p99() * 1e3);
            maxNs[i] = Math.round(t.execUs().max() * 1e3);
        }
        long[] rP99 = responseTimes(p99Ns, periodNs, deadlineNs);
        long[] rMax = responseTimes(maxNs, periodNs, deadlineNs);
        List<TaskUtilization> rows = new ArrayList<>();
        double uP99 = 0;
        double uMax = 0;
        boolean allP99 = true;
        boolean allMax = true;
        String firstFailure = null;
        for (int i = 0; i < n; i++) {
            TaskReport t = periodic.get(i);
            double u99 = (double) p99Ns[i] / periodNs[i];
            double uMx = (double) maxNs[i] / periodNs[i];
            uP99 += u99;
            uMax += uMx;
            boolean ok99 = rP99[i] >= 0;
            boolean okMax = rMax[i] >= 0;
            allP99 &= ok99;
            allMax &= okMax;
            if (!ok99 && firstFailure == null) {
                firstFailure = t.name();
            }
            rows.add(new TaskUtilization(t.name(), i + 1, t.periodMs(), deadlineNs[i] / 1e6, p99Ns[i] / 1e6,
                    maxNs[i] / 1e6, round4(u99), round4(uMx), ok99 ? rP99[i] / 1e6 : null,
                    okMax ? rMax[i] / 1e6 : null, ok99, okMax));
        }
        double bound = liuLaylandBound(n);
        boolean llHolds = uP99 <= bound;
        return new SchedulabilityReport(cores, rows, excluded, round4(uP99), round4(uMax), round4(bound), llHolds,
                allP99, allMax, round4(uP99 / cores), round4(uMax / cores),
                verdict(n, cores, uP99, llHolds, allP99, allMax, firstFailure));
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
        int n = execNs.length;
        long[] response = new long[n];
        for (int i = 0; i < n; i++) {
            long r = execNs[i];
            while (true) {
                long next = execNs[i];
                for (int j = 0; j < i; j++) {
                    next += ceilDiv(r, periodNs[j]) * execNs[j];
                }
                if (next > deadlineNs[i]) {
                    r = -1;
                    break;
                }
                if (next == r) {
                    break;
                }
                r = next;
            }
            response[i] = r;
        }
        return response;
    }

    private static long ceilDiv(long a, long b) {
        return -Math.floorDiv(-a, b);
    }

    private static String verdict(int n, int cores, double uP99, boolean llHolds, boolean rtaP99, boolean rtaMax,
                                  String firstFailure) {
        if (n == 0) {
            return "no periodic tasks to analyze";
        }
        StringBuilder sb = new StringBuilder();
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
