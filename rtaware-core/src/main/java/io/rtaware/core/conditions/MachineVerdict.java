package io.rtaware.core.conditions;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Whether the machine, not the controller, could have caused what a run measured, by one
 * stated rule with named thresholds:
 *
 * <ul>
 *   <li>{@code busy}: other processes used more than {@link #OTHER_CPUS_MAX} of one CPU on
 *       average over the span, or the hypervisor stole more than {@link #STEAL_MAX_PCT} % of
 *       the machine's CPU time;</li>
 *   <li>{@code disturbed} (and not busy): the JVM stopped the run's threads for longer than
 *       {@link #PAUSE_PERIOD_FRACTION} of the shortest period (in wall time), in a collection or
 *       in reaching a safepoint, more often than {@link #LONG_STOPS_PER_1000_PERIODS_MAX} times per
 *       1000 such periods. One such stop can delay one release of each task; a handful in a run
 *       of tens of thousands of releases (ZGC's cycles, the JIT's safepoints, about 0.1-0.5 ms
 *       each on the development VM) cannot explain a miss rate, a steady stream of them can;</li>
 *   <li>{@code disturbed} too: the whole process was stopped for longer than
 *       {@link #STALL_MIN_MS} ms and than the shortest period (in wall time), as its own watcher
 *       thread saw it (a {@code SIGSTOP}, a frozen VM, a swap storm: no CPU counter shows these);</li>
 *   <li>{@code quiet}: none of these;</li>
 *   <li>{@code unknown}: the OS does not expose the CPU counters (not Linux).</li>
 * </ul>
 *
 * Every figure that crossed its threshold is named in {@link #reasons()}.
 *
 * @param verdict {@link #QUIET}, {@link #BUSY}, {@link #DISTURBED} or {@link #UNKNOWN}
 * @param reasons each figure that crossed its threshold, with the threshold; for a quiet
 *     machine, the figures that were below them
 * @param context the load average at the start, for the reader (not part of the rule)
 */
public record MachineVerdict(String verdict, List<String> reasons, String context) {

    /** No figure crossed a threshold. */
    public static final String QUIET = "quiet";
    /** Other processes or the hypervisor took CPU time. */
    public static final String BUSY = "busy";
    /** The JVM paused the run for a tenth of its shortest period or more. */
    public static final String DISTURBED = "disturbed";
    /** The OS gives no CPU counters. */
    public static final String UNKNOWN = "unknown";

    /** CPU used by other processes above which the machine is busy, in CPUs (10 % of one CPU). */
    public static final double OTHER_CPUS_MAX = 0.10;
    /** Steal above which the machine is busy, percent of its CPU time. */
    public static final double STEAL_MAX_PCT = 2.0;
    /** A JVM pause longer than this share of the shortest period disturbs the run. */
    public static final double PAUSE_PERIOD_FRACTION = 0.1;
    /** Long stops (see {@link #PAUSE_PERIOD_FRACTION}) per 1000 shortest periods above which the run is disturbed. */
    public static final double LONG_STOPS_PER_1000_PERIODS_MAX = 1.0;

    /** A stop of the whole process longer than this (and than the shortest period) disturbs the run, ms. */
    public static final double STALL_MIN_MS = 100;

    /** The rule, in words, as written in reports. */
    public static final String RULE = String.format(Locale.ROOT,
            "busy if other processes used more than %.2f of one CPU or steal was above %.0f %%; disturbed if the JVM "
                    + "stopped the threads (a GC pause or a time to safepoint) for longer than %.1f of the shortest period in "
                    + "wall time more than %.0f times per 1000 such periods, or if the whole process was stopped for longer "
                    + "than %.0f ms and the shortest period; quiet otherwise",
            OTHER_CPUS_MAX, STEAL_MAX_PCT, PAUSE_PERIOD_FRACTION, LONG_STOPS_PER_1000_PERIODS_MAX, STALL_MIN_MS);

    /**
     * Copies the list.
     *
     * @param verdict {@link #QUIET}, {@link #BUSY}, {@link #DISTURBED} or {@link #UNKNOWN}
     * @param reasons each figure that crossed its threshold, with the threshold (copied)
     * @param context the load average at the start, for the reader
     */
    public MachineVerdict {
        reasons = List.copyOf(reasons);
    }

    /**
     * @param m the measured span
     * @param shortestPeriodMs the shortest task period of the run in wall-clock ms (a world
     *     period divided by the time scale), or NaN when it has none (then pauses are not judged);
     *     {@code m}'s long stops are counted against a tenth of it
     * @return the verdict by the rule
     */
    public static MachineVerdict of(MeasuredConditions m, double shortestPeriodMs) {
        String context = Double.isFinite(m.loadStart()) ? String.format(Locale.ROOT, "load %.1f at start", m.loadStart())
                : "";
        if (!Double.isFinite(m.otherCpus())) {
            return new MachineVerdict(UNKNOWN, List.of("no CPU counters (/proc/stat) on this OS"), context);
        }
        List<String> busy = new ArrayList<>();
        String others = String.format(Locale.ROOT, "other processes used %s of %d CPUs", cpus(m.otherCpus()),
                m.machineCpus());
        if (m.otherCpus() > OTHER_CPUS_MAX) {
            busy.add(others + " (more than " + cpus(OTHER_CPUS_MAX) + ")");
        }
        if (Double.isFinite(m.stealPct()) && m.stealPct() > STEAL_MAX_PCT) {
            busy.add(String.format(Locale.ROOT, "steal %.1f %% (above %.0f %%)", m.stealPct(), STEAL_MAX_PCT));
        }
        List<String> disturbed = new ArrayList<>();
        String stops = null;
        if (Double.isFinite(shortestPeriodMs) && shortestPeriodMs > 0 && m.longStops() >= 0) {
            double periods = m.durationS() * 1000.0 / shortestPeriodMs;
            Double ttsp = m.timeToSafepointMaxMs();
            stops = String.format(Locale.ROOT, "%d JVM stops longer than %s ms (%.1f of the shortest period, %s ms of wall "
                    + "time) in %.0f such periods", m.longStops(), ms(m.longStopLimitMs()), PAUSE_PERIOD_FRACTION,
                    ms(shortestPeriodMs), periods);
            String longest = "longest GC pause " + ms(m.gcMaxPauseMs()) + " ms, longest time to safepoint "
                    + (ttsp == null ? "not measured" : ms(ttsp) + " ms");
            if (m.longStops() > LONG_STOPS_PER_1000_PERIODS_MAX * periods / 1000.0) {
                disturbed.add(String.format(Locale.ROOT, "%s, more than %.0f per 1000 (%s)", stops,
                        LONG_STOPS_PER_1000_PERIODS_MAX, longest));
            }
            stops += " (" + longest + ")";
        }
        if (Double.isFinite(m.longestStallMs()) && m.longestStallMs() > STALL_MIN_MS
                && !(Double.isFinite(shortestPeriodMs) && m.longestStallMs() <= shortestPeriodMs)) {
            disturbed.add(String.format(Locale.ROOT, "the whole process was stopped for %s ms (its own watcher thread "
                    + "woke that late; more than %.0f ms%s)", ms(m.longestStallMs()), STALL_MIN_MS,
                    Double.isFinite(shortestPeriodMs) ? " and the shortest period, " + ms(shortestPeriodMs) + " ms" : ""));
        }
        if (!busy.isEmpty()) {
            List<String> all = new ArrayList<>(busy);
            all.addAll(disturbed);
            return new MachineVerdict(BUSY, all, context);
        }
        if (!disturbed.isEmpty()) {
            return new MachineVerdict(DISTURBED, disturbed, context);
        }
        List<String> below = new ArrayList<>();
        below.add(others);
        if (Double.isFinite(m.stealPct())) {
            below.add(String.format(Locale.ROOT, "steal %.1f %%", m.stealPct()));
        }
        if (stops != null) {
            below.add(stops);
        } else if (m.gcCount() > 0) {
            below.add("longest GC pause " + ms(m.gcMaxPauseMs()) + " ms");
        }
        return new MachineVerdict(QUIET, below, context);
    }

    /** @return true if the verdict is {@link #QUIET} */
    public boolean quiet() {
        return QUIET.equals(verdict);
    }

    /** @return the one line for the run's summary, e.g. {@code machine: busy (other processes used 1.6 of 2 CPUs; load 14.2 at start)} */
    public String text() {
        List<String> parts = new ArrayList<>(reasons);
        if (!context.isEmpty()) {
            parts.add(context);
        }
        return "machine: " + verdict + " (" + String.join("; ", parts) + ")";
    }

    private static String cpus(double v) {
        return String.format(Locale.ROOT, v < 1 ? "%.2f" : "%.1f", v);
    }

    private static String ms(double v) {
        return String.format(Locale.ROOT, v < 10 ? "%.2f" : "%.1f", v);
    }
}
