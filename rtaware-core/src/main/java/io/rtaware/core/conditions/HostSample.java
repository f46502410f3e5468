package io.rtaware.core.conditions;

import java.util.Map;

/**
 * One reading of the machine's counters, taken at the start and at the end of a span; the
 * difference of two is what happened in between ({@link MeasuredConditions#between}). A
 * counter the OS does not expose is -1 (NaN for the load).
 *
 * @param nanoTime when it was taken, {@link System#nanoTime()} scale
 * @param load1 the one-minute load average ({@code /proc/loadavg}), or NaN
 * @param cpus CPUs counted in {@code /proc/stat} ({@code cpuN} lines), or -1
 * @param totalTicks all CPU time of the machine since boot, clock ticks, or -1
 * @param busyTicks the part of it not idle, not waiting for I/O and not stolen, or -1
 * @param stealTicks time the hypervisor gave this machine's CPUs to others, or -1
 * @param selfTicks CPU time of this process (user + system, all its threads), or -1
 * @param involuntarySwitches involuntary context switches of this process's live threads, or -1
 * @param otherTicks per process id, every other process's and kernel thread's CPU time (user +
 *     system, plus that of its children it has reaped) by its own counters, or null where the
 *     process table cannot be read whole (no per-process files, or {@code /proc} mounted with
 *     {@code hidepid})
 * @param hugePagesPct the share of this process's resident memory mapped in huge pages, percent, or
 *     NaN where not readable
 */
public record HostSample(long nanoTime, double load1, int cpus, long totalTicks, long busyTicks, long stealTicks,
                         long selfTicks, long involuntarySwitches, Map<Long, Long> otherTicks, double hugePagesPct) {

    /**
     * Keeps an unmodifiable copy of the process table.
     *
     * @param nanoTime when it was taken, {@link System#nanoTime()} scale
     * @param load1 the one-minute load average, or NaN
     * @param cpus CPUs counted, or -1
     * @param totalTicks all CPU time of the machine since boot, clock ticks, or -1
     * @param busyTicks the part of it not idle, not waiting for I/O and not stolen, or -1
     * @param stealTicks time the hypervisor gave this machine's CPUs to others, or -1
     * @param selfTicks CPU time of this process, or -1
     * @param involuntarySwitches involuntary context switches of this process's live threads, or -1
     * @param otherTicks per process id, every other process's CPU time (copied), or null
     * @param hugePagesPct the share of this process's resident memory in huge pages, percent, or NaN
     */
    public HostSample {
        otherTicks = otherTicks == null ? null : Map.copyOf(otherTicks);
    }
}
