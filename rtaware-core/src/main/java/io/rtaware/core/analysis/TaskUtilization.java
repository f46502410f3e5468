package io.rtaware.core.analysis;

/**
 * One periodic task in the schedulability analysis. Serialized in snake_case. Immutable.
 *
 * @param task the task's name
 * @param rmPriority rate-monotonic rank: 1 is the highest priority (shortest period)
 * @param periodMs period, ms
 * @param deadlineMs relative deadline, ms
 * @param execP99Ms p99 execution time, ms
 * @param execMaxMs largest execution time, ms
 * @param utilizationP99 {@code execP99 / period}
 * @param utilizationMax {@code execMax / period}
 * @param responseP99Ms worst-case response time on one core with p99 execution times, ms, or
 *     null if it exceeds the deadline
 * @param responseMaxMs the same with the largest execution times, ms, or null
 * @param meetsDeadlineP99 true if {@code responseP99Ms <= deadlineMs}
 * @param meetsDeadlineMax true if {@code responseMaxMs <= deadlineMs}
 * @param responseP99MsOnCores the response-time bound on the analysis's cores with p99
 *     execution times, ms ({@link Schedulability#testOnCores}), or null if it exceeds the deadline
 *     or a higher-priority task's does; on one core the same as {@code responseP99Ms}
 * @param meetsDeadlineP99OnCores true if {@code responseP99MsOnCores} is not null
 */
public record TaskUtilization(String task, int rmPriority, double periodMs, double deadlineMs, double execP99Ms,
                              double execMaxMs, double utilizationP99, double utilizationMax, Double responseP99Ms,
                              Double responseMaxMs, boolean meetsDeadlineP99, boolean meetsDeadlineMax,
                              Double responseP99MsOnCores, boolean meetsDeadlineP99OnCores) {
}
