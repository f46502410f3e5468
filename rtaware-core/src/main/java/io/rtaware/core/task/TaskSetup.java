package io.rtaware.core.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.time.Clock;
import java.time.Duration;

/**
 * What a task may do during initialization: declare the keys it produces and consumes. The
 * returned handles are used during execution. Valid only inside
 * {@link Task#initialize(TaskSetup)}; not thread-safe.
 */
public interface TaskSetup {

    /** @return the task's registered name */
    String taskName();

    /** @return the task's schedule */
    Schedule schedule();

    /** @return the world clock the task runs on */
    Clock clock();

    /**
     * Declares that this task reads a key.
     *
     * @param key the key; exactly one task must produce it, with the same type
     * @param <T> the value type
     * @return the input handle, with a buffer this task owns
     */
    <T extends StateValue<T>> Input<T> consume(Key<T> key);

    /**
     * Declares that this task reads a key and that values older than {@code maxAge} are not to
     * be trusted: reading one is reported as an expired read, and {@link Input#isExpired()}
     * tells the task so it can act on it.
     *
     * @param key the key
     * @param maxAge the maximum age of a value this task accepts, in world time
     * @param <T> the value type
     * @return the input handle
     */
    <T extends StateValue<T>> Input<T> consume(Key<T> key, Duration maxAge);

    /**
     * Declares that this task writes a key; no other task may.
     *
     * @param key the key
     * @param <T> the value type
     * @return the output handle, with a buffer this task owns
     */
    <T extends StateValue<T>> Output<T> produce(Key<T> key);

    /**
     * Declares that this task turns an input into motion and must react within a distance:
     * the run's report carries the declaration with the task, and the period advice checks the
     * task's period against it ({@code reaction} rule). At most one per task; a later
     * declaration replaces an earlier one. Setups that do not build a report (test doubles)
     * may ignore it, which this default does.
     *
     * @param constraint the reaction the task must achieve
     */
    default void declareReaction(ReactionConstraint constraint) {
    }
}
