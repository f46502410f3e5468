package io.rtaware.core.analysis;

import java.util.List;

/**
 * The report's {@code schedulability} section. Serialized in snake_case. Immutable.
 *
 * @param cores the core count the per-core figures are for
 * @param tasks the periodic tasks in rate-monotonic order (highest priority first)
 * @param excludedTasks tasks without a period (continuous, once), which the analysis cannot
 *     bound
 * @param utilizationP99 sum of the tasks' p99 utilizations
 * @param utilizationMax sum of the tasks' max utilizations
 * @param liuLaylandBound {@code n (2^(1/n) - 1)} for the n periodic tasks (1 for n = 0)
 * @param liuLaylandHoldsP99 true if {@code utilizationP99 <= liuLaylandBound}: schedulable under
 *     rate-monotonic priorities on one core by the sufficient test
 * @param rtaSchedulableP99 true if every task meets its deadline in the exact response-time
 *     analysis on one core with p99 execution times
 * @param rtaSchedulableMax the same with the largest execution times
 * @param utilizationPerCoreP99 {@code utilizationP99 / cores}
 * @param utilizationPerCoreMax {@code utilizationMax / cores}
 * @param rtaSchedulableP99OnCores true if every task meets its deadline by the response-time test
 *     on {@code cores} cores with p99 execution times ({@code rtaTestOnCores})
 * @param rtaTestOnCores the name of that test: the exact analysis on one core, a sufficient
 *     bound for global fixed-priority scheduling on more
 * @param verdict one line a person reads
 */
public record SchedulabilityReport(int cores, List<TaskUtilization> tasks, List<String> excludedTasks,
                                   double utilizationP99, double utilizationMax, double liuLaylandBound,
                                   boolean liuLaylandHoldsP99, boolean rtaSchedulableP99, boolean rtaSchedulableMax,
                                   double utilizationPerCoreP99, double utilizationPerCoreMax,
                                   boolean rtaSchedulableP99OnCores, String rtaTestOnCores, String verdict) {

    /**
     * Copies the lists so the report stays immutable.
     *
     * @param cores the core count the per-core figures are for
     * @param tasks the periodic tasks in rate-monotonic order (highest priority first)
     * @param excludedTasks tasks without a period (continuous, once), which the analysis cannot bound
     * @param utilizationP99 sum of the tasks' p99 utilizations
     * @param utilizationMax sum of the tasks' max utilizations
     * @param liuLaylandBound {@code n (2^(1/n) - 1)} for the n periodic tasks (1 for n = 0)
     * @param liuLaylandHoldsP99 true if {@code utilizationP99 <= liuLaylandBound}: schedulable under
     *     rate-monotonic priorities on one core by the sufficient test
     * @param rtaSchedulableP99 true if every task meets its deadline in the exact response-time analysis on one
     *     core with p99 execution times
     * @param rtaSchedulableMax the same with the largest execution times
     * @param utilizationPerCoreP99 {@code utilizationP99 / cores}
     * @param utilizationPerCoreMax {@code utilizationMax / cores}
     * @param rtaSchedulableP99OnCores true if every task meets its deadline by the test on {@code cores} cores
     * @param rtaTestOnCores the name of that test
     * @param verdict one line a person reads
     */
    public SchedulabilityReport {
        tasks = List.copyOf(tasks);
        excludedTasks = List.copyOf(excludedTasks);
    }
}
