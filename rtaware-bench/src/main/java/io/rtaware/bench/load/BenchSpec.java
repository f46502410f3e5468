package io.rtaware.bench.load;

import io.rtaware.core.time.Durations;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * One synthetic task of a bench set.
 *
 * @param name task name
 * @param periodNs period in world nanoseconds (the initial one, if a range is given)
 * @param workNs CPU work per cycle in wall nanoseconds
 * @param minPeriodNs shortest period with {@code --adaptive} ({@code periodNs} if fixed)
 * @param maxPeriodNs longest period with {@code --adaptive} ({@code periodNs} if fixed)
 * @param offsetNs first release after the start, in world nanoseconds (0 unless {@code --stagger})
 */
public record BenchSpec(String name, long periodNs, long workNs, long minPeriodNs, long maxPeriodNs, long offsetNs) {

    /**
     * A fixed period, first released at the start.
     *
     * @param name task name
     * @param periodNs period
     * @param workNs work per cycle
     */
    public BenchSpec(String name, long periodNs, long workNs) {
        this(name, periodNs, workNs, periodNs, periodNs, 0);
    }

    /** @return the task's schedule: periodic, with its offset and the period range if one was given */
    public io.rtaware.core.task.Schedule.Periodic schedule() {
        return new io.rtaware.core.task.Schedule.Periodic(periodNs, offsetNs, periodNs, minPeriodNs, maxPeriodNs);
    }

    /**
     * Spreads the first releases of a task set over the tasks' periods: task i of n (from 0) is
     * first released {@code floor(i * period / n)} after the start, so n tasks of one period are
     * released one {@code period / n} apart instead of all at the same instant (the releases of a
     * real controller's tasks are staggered the same way with their schedules' offsets).
     *
     * @param specs the tasks, in order
     * @return the same tasks with their offsets set
     */
    public static List<BenchSpec> staggered(List<BenchSpec> specs) {
        List<BenchSpec> out = new ArrayList<>(specs.size());
        int n = specs.size();
        for (int i = 0; i < n; i++) {
            BenchSpec s = specs.get(i);
            // floor(i * period / n) without overflow: period = q * n + r, so it is i * q + floor(i * r / n).
            long offsetNs = i * (s.periodNs() / n) + (long) i * (s.periodNs() % n) / n;
            out.add(new BenchSpec(s.name(), s.periodNs(), s.workNs(), s.minPeriodNs(), s.maxPeriodNs(), offsetNs));
        }
        return out;
    }

    /**
     * Parses {@code --spec "a:10ms:2ms,b:50ms:20ms"}; a period may be a range
     * {@code min..max} (e.g. {@code b:20ms..100ms:20ms}), which starts at min and moves only with
     * {@code --adaptive}.
     *
     * @param text the spec list
     * @return the tasks, in order
     * @throws IllegalArgumentException naming the bad entry
     */
    public static List<BenchSpec> parseList(String text) {
        List<BenchSpec> specs = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (String entry : text.split(",")) {
            String[] parts = entry.trim().split(":");
            if (parts.length != 3 || parts[0].isBlank()) {
                throw new IllegalArgumentException("--spec entry '" + entry.trim() + "' is not name:period:work (example: a:10ms:2ms)");
            }
            if (!names.add(parts[0])) {
                throw new IllegalArgumentException("--spec names task '" + parts[0] + "' twice");
            }
            String[] range = parts[1].split("\\.\\.", -1);
            if (range.length == 2) {
                long min = parse(range[0], "period", entry);
                long max = parse(range[1], "period", entry);
                BenchSpec fixed = of(parts[0], min, parse(parts[2], "work", entry));
                if (max < min) {
                    throw new IllegalArgumentException("--spec entry '" + entry.trim() + "': period range " + parts[1]
                            + " has its maximum below its minimum");
                }
                specs.add(new BenchSpec(fixed.name(), min, fixed.workNs(), min, max, 0));
            } else {
                specs.add(of(parts[0], parse(parts[1], "period", entry), parse(parts[2], "work", entry)));
            }
        }
        return specs;
    }

    /**
     * @param name task name
     * @param periodNs period
     * @param workNs work
     * @return the validated spec
     * @throws IllegalArgumentException if the period is not positive or the work negative
     */
    public static BenchSpec of(String name, long periodNs, long workNs) {
        if (periodNs <= 0) {
            throw new IllegalArgumentException("period of task '" + name + "' must be positive, got " + Durations.format(periodNs));
        }
        if (workNs < 0) {
            throw new IllegalArgumentException("work of task '" + name + "' cannot be negative, got " + workNs + "ns");
        }
        return new BenchSpec(name, periodNs, workNs);
    }

    private static long parse(String value, String what, String entry) {
        try {
            return Durations.parseNanos(value);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--spec entry '" + entry.trim() + "': " + what + " " + e.getMessage());
        }
    }
}
