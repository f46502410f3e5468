package io.rtaware.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import io.rtaware.core.task.ReactionConstraint;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One task's timing over a run. Times are world time.
 *
 * @param name the task's name
 * @param schedule {@code periodic}, {@code continuous} or {@code once}
 * @param periodMs period in ms (null unless periodic)
 * @param deadlineMs relative deadline in ms (null unless periodic)
 * @param offsetMs first release after the start in ms (null unless periodic; absent from reports
 *     written before issue 16, which read as null)
 * @param releases grid points at which the task was due (periodic: runs plus skipped)
 * @param runs cycles executed
 * @param misses releases whose run did not finish by the deadline, plus every skipped release
 * @param missPct {@code 100 * misses / releases}
 * @param skipped releases skipped because the task was still running
 * @param staleRuns cycles in which none of the task's inputs had new data
 * @param errors cycles that threw
 * @param expiredReads reads of an input older than its declared maximum age (one per input per cycle)
 * @param execUs execution time per cycle, microseconds
 * @param latenessUs start of the cycle minus its scheduled release, microseconds
 * @param listenerErrors faults of listeners (and the trace recorder) on this task's events,
 *     contained by the monitor: the task went on regardless
 * @param reaction the reaction the task declared ({@link ReactionConstraint}), or null; written
 *     to JSON as {@code reaction} only when declared, so other tasks keep the schema's fields
 * @param inputMaxAgeMs the freshness contracts the task declared: per input key, the oldest
 *     value it accepts, ms ({@code TaskSetup.consume(key, maxAge)}); empty when it declared none,
 *     and then absent from JSON (reports written before issue 34 read as empty)
 */
public record TaskReport(String name, String schedule, Double periodMs, Double deadlineMs,
                         @JsonInclude(JsonInclude.Include.NON_NULL) Double offsetMs, long releases, long runs, long misses, double missPct, long skipped,
                         long staleRuns, long errors, long expiredReads,
                         Percentiles execUs, Percentiles latenessUs, long listenerErrors,
                         @JsonInclude(JsonInclude.Include.NON_NULL) ReactionConstraint reaction,
                         @JsonInclude(JsonInclude.Include.NON_EMPTY) Map<String, Double> inputMaxAgeMs) {

    /**
     * Copies the freshness contracts so the report stays immutable; null reads as none.
     *
     * @param name the task's name
     * @param schedule the schedule kind
     * @param periodMs period in ms or null
     * @param deadlineMs deadline in ms or null
     * @param offsetMs first release after the start in ms, or null
     * @param releases releases
     * @param runs runs
     * @param misses misses
     * @param missPct miss percentage
     * @param skipped skipped releases
     * @param staleRuns stale runs
     * @param errors errors
     * @param expiredReads expired reads
     * @param execUs execution time percentiles
     * @param latenessUs lateness percentiles
     * @param listenerErrors contained listener faults
     * @param reaction the declared reaction, or null
     * @param inputMaxAgeMs the declared maximum age per input key, ms, or null for none
     */
    public TaskReport {
        inputMaxAgeMs = inputMaxAgeMs == null ? Map.of() : Collections.unmodifiableMap(new LinkedHashMap<>(inputMaxAgeMs));
    }

    /**
     * A report without an offset, listener faults or a reaction (for reports built outside a
     * monitor).
     *
     * @param name the task's name
     * @param schedule the schedule kind
     * @param periodMs period in ms or null
     * @param deadlineMs deadline in ms or null
     * @param releases releases
     * @param runs runs
     * @param misses misses
     * @param missPct miss percentage
     * @param skipped skipped releases
     * @param staleRuns stale runs
     * @param errors errors
     * @param expiredReads expired reads
     * @param execUs execution time percentiles
     * @param latenessUs lateness percentiles
     */
    public TaskReport(String name, String schedule, Double periodMs, Double deadlineMs, long releases, long runs,
                      long misses, double missPct, long skipped, long staleRuns, long errors, long expiredReads,
                      Percentiles execUs, Percentiles latenessUs) {
        this(name, schedule, periodMs, deadlineMs, null, releases, runs, misses, missPct, skipped, staleRuns,
                errors, expiredReads, execUs, latenessUs, 0, null, Map.of());
    }

    /**
     * @param constraint the task's declared reaction
     * @return a copy carrying it
     */
    public TaskReport withReaction(ReactionConstraint constraint) {
        return new TaskReport(name, schedule, periodMs, deadlineMs, offsetMs, releases, runs, misses, missPct,
                skipped, staleRuns, errors, expiredReads, execUs, latenessUs, listenerErrors, constraint, inputMaxAgeMs);
    }

    /**
     * @param maxAgeMs the task's declared maximum age per input key, ms
     * @return a copy carrying them
     */
    public TaskReport withInputMaxAges(Map<String, Double> maxAgeMs) {
        return new TaskReport(name, schedule, periodMs, deadlineMs, offsetMs, releases, runs, misses, missPct,
                skipped, staleRuns, errors, expiredReads, execUs, latenessUs, listenerErrors, reaction, maxAgeMs);
    }
}
