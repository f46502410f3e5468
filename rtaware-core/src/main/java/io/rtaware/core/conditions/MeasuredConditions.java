package io.rtaware.core.conditions;

import java.util.Map;

/**
 * What happened on the machine and in the JVM over a span (a run, or the check before one),
 * measured from the OS's counters and the JVM's notifications, not estimated. A figure that
 * could not be measured is NaN (null in JSON), or -1 for counts.
 *
 * @param durationS the span's wall-clock length, s
 * @param loadStart the one-minute load average at the start
 * @param loadEnd the one-minute load average at the end
 * @param machineCpus the CPUs the OS counts
 * @param otherCpus CPU used by other processes over the span, in CPUs, never more than the
 *     machine's CPUs: the growth of every other process's and kernel thread's own CPU counters
 *     ({@code /proc/PID/stat}), held within {@link #TICK_NOISE_FRACTION} of this process's CPU (at
 *     least {@link #TICK_NOISE_MIN_CPUS}) of the machine's busy time ({@code /proc/stat}) minus this
 *     process's ({@code /proc/self/stat}): the counters of each process are exact but miss
 *     children reaped where nobody counts them (a parent that ignores {@code SIGCHLD}) and count
 *     twice a child's whole life when a parent reaps it late, while the machine's busy time
 *     sees all CPU time but is sampled at the timer tick. Where the process table cannot be read
 *     whole, the machine's figure alone
 * @param stealPct CPU time the hypervisor gave to other guests, percent of the machine's
 * @param gcCount collections that paused the application threads
 * @param gcTotalMs their summed duration, ms
 * @param gcMaxPauseMs the longest, ms
 * @param safepoints safepoints over the span (the JVM's safepoint log), or -1 where not measured
 * @param timeToSafepointMaxMs the longest time to reach one of them, ms (0 with none), or null where not measured
 * @param safepointNote null when the time to safepoint is measured, else why not
 * @param longStopLimitMs the length, ms of wall time, above which a JVM stop counts in
 *     {@code longStops} (a tenth of the run's shortest period in wall time), or NaN when not judged
 * @param longStops the JVM's stops (a collection's longest pause, a safepoint's time to reach)
 *     longer than {@code longStopLimitMs}, or -1 when not judged
 * @param involuntarySwitches involuntary context switches of this process's threads over the span
 * @param longestStallMs the longest the whole process was stopped over the span, ms, as its own
 *     watcher thread saw it ({@link JvmProbe.PauseWatch#longestStallMs()}), or NaN where not measured
 * @param timerSlackNs the largest timer slack, ns, of the threads that ran the cycles, as each read
 *     it from {@code /proc} after its setup ({@link ThreadTimerSlack}): Linux's default is 50 000 ns,
 *     rtaware's real-time layer asks for 1; null where not known (no such threads, no {@code /proc})
 * @param hugePagesPct the share of this process's resident memory mapped in huge pages at the
 *     span's end, percent (with the launcher's defaults, on a kernel that gives shared memory huge
 *     pages, the heap is: see docs/performance.md, "JVM choice"), or NaN where not measured
 */
public record MeasuredConditions(double durationS, double loadStart, double loadEnd, int machineCpus,
                                 double otherCpus, double stealPct, long gcCount, double gcTotalMs,
                                 double gcMaxPauseMs, long safepoints, Double timeToSafepointMaxMs, String safepointNote,
                                 double longStopLimitMs, long longStops, long involuntarySwitches,
                                 double longestStallMs, Long timerSlackNs, double hugePagesPct) {

    /**
     * How far, as a share of this process's own CPU, the machine's tick-sampled busy time minus
     * this process's was seen to stray from the exact per-process counters with nothing else
     * running (-0.12 to +0.10 CPUs over three paper-course runs of about one CPU, 2-vCPU VM,
     * 2026-11-26; see {@link HostReader}), with a margin.
     */
    public static final double TICK_NOISE_FRACTION = 0.15;
    /** The least that noise is taken to be, CPUs (a few ticks of a short span). */
    public static final double TICK_NOISE_MIN_CPUS = 0.05;

    /**
     * @param start the counters at the start
     * @param end the counters at the end
     * @param pauses the JVM's pauses over the span, or null when they are not part of it (the
     *     check of the machine before a run)
     * @param longStopLimitMs the stop length, ms, above which stops are counted, or NaN for none
     * @return the difference
     */
    public static MeasuredConditions between(HostSample start, HostSample end, JvmProbe.PauseWatch pauses,
                                             double longStopLimitMs) {
        double durationS = (end.nanoTime() - start.nanoTime()) / 1e9;
        long total = known(start.totalTicks(), end.totalTicks());
        long busy = known(start.busyTicks(), end.busyTicks());
        long steal = known(start.stealTicks(), end.stealTicks());
        long self = known(start.selfTicks(), end.selfTicks());
        int cpus = end.cpus();
        double other = Double.NaN;
        double stealPct = Double.NaN;
        if (total > 0 && cpus > 0) {
            double perTick = (double) cpus / total;
            long others = othersTicks(start.otherTicks(), end.otherTicks());
            double machine = busy >= 0 ? (busy - Math.max(0, self)) * perTick : Double.NaN;
            if (others >= 0) {
                other = others * perTick;
                if (Double.isFinite(machine)) {
                    double noise = Math.max(TICK_NOISE_MIN_CPUS, TICK_NOISE_FRACTION * Math.max(0, self) * perTick);
                    other = Math.min(Math.max(other, machine - noise), machine + noise);
                }
            } else {
                other = machine;
            }
            // Neither figure can be negative or above the machine's CPUs less nothing.
            other = Double.isFinite(other) ? Math.min(Math.max(0, other), cpus) : other;
            if (steal >= 0) {
                stealPct = 100.0 * steal / total;
            }
        }
        long switches = known(start.involuntarySwitches(), end.involuntarySwitches());
        return new MeasuredConditions(durationS, start.load1(), end.load1(), cpus, other, stealPct,
                pauses == null ? 0 : pauses.gcCount(), pauses == null ? 0 : pauses.gcTotalMs(),
                pauses == null ? 0 : pauses.gcMaxPauseMs(), pauses == null ? -1 : pauses.safepoints(),
                pauses == null ? null : pauses.maxTimeToSafepointMs(),
                pauses == null ? "not part of this span" : pauses.safepointNote(), longStopLimitMs,
                pauses == null || Double.isNaN(longStopLimitMs) ? -1 : pauses.stopsLongerThan(longStopLimitMs), switches,
                pauses == null ? Double.NaN : pauses.longestStallMs(), null,
                end.hugePagesPct());
    }

    /**
     * CPU time of the other processes between two process tables: each process's growth, and all
     * of a process that is new (or whose counters went down: its id was taken by a new one). A
     * process that ended is counted where its parent reaped it (the parent's children's time); if
     * it lived before the span, that part is counted too, which errs towards busy ({@link #between}
     * holds the sum near the machine's busy time).
     *
     * @return ticks, or -1 when either table is missing
     */
    /**
     * @param slack the observation of the threads that ran the cycles
     * @return these conditions with the largest slack observed, or null if none was
     */
    public MeasuredConditions withTimerSlack(ThreadTimerSlack slack) {
        Long ns = slack.largestNs().isPresent() ? slack.largestNs().getAsLong() : null;
        return new MeasuredConditions(durationS, loadStart, loadEnd, machineCpus, otherCpus, stealPct, gcCount,
                gcTotalMs, gcMaxPauseMs, safepoints, timeToSafepointMaxMs, safepointNote, longStopLimitMs, longStops,
                involuntarySwitches, longestStallMs, ns, hugePagesPct);
    }

    static long othersTicks(Map<Long, Long> start, Map<Long, Long> end) {
        if (start == null || end == null) {
            return -1;
        }
        long sum = 0;
        for (Map.Entry<Long, Long> e : end.entrySet()) {
            long before = start.getOrDefault(e.getKey(), 0L);
            long grew = e.getValue() - before;
            sum += grew >= 0 ? grew : e.getValue();
        }
        return sum;
    }

    private static long known(long a, long b) {
        return a < 0 || b < 0 ? -1 : b - a;
    }
}
