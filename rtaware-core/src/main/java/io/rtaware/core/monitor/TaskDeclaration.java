package io.rtaware.core.monitor;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.task.ReactionConstraint;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import java.util.List;
import java.util.Objects;

/**
 * What a task declares when it is initialized ({@link TaskSetup}): the keys it consumes, each with
 * the largest age it accepts, the keys it produces, and the reaction it must achieve. The monitor
 * reads the same declarations through the same setup when it builds; {@link #of(TaskSpec)} reads
 * them without a monitor, for a tool that must know a task's data before it runs the task (replay
 * finds which recorded channels feed a task and which it writes). Immutable.
 *
 * @param task the task's name
 * @param inputs the keys it consumes, in declaration order: the order of the input generations in
 *     {@link MonitorListener#onCycleRecord} and of {@link TaskInfo#inputKeys()}
 * @param outputs the keys it produces, in declaration order
 * @param reaction the reaction it declared ({@link TaskSetup#declareReaction}), or null for none
 */
public record TaskDeclaration(String task, List<DeclaredInput> inputs, List<Key<?>> outputs,
                              ReactionConstraint reaction) {

    /**
     * One consumed key.
     *
     * @param key the key (its name and value type)
     * @param maxAgeNs the largest age of a value the task accepts, world time, or
     *     {@link Long#MAX_VALUE} when it declared none (as {@link Input#maxAgeNs()})
     */
    public record DeclaredInput(Key<?> key, long maxAgeNs) {

        /**
         * @param key the key
         * @param maxAgeNs the largest age accepted, or {@link Long#MAX_VALUE} for none
         */
        public DeclaredInput {
            Objects.requireNonNull(key, "key");
        }

        /** @return true if the task declared a largest age for this input */
        public boolean hasMaxAge() {
            return maxAgeNs != Long.MAX_VALUE;
        }
    }

    /**
     * @param task the task's name
     * @param inputs the keys it consumes, in declaration order (copied)
     * @param outputs the keys it produces, in declaration order (copied)
     * @param reaction the reaction it declared, or null
     */
    public TaskDeclaration {
        Objects.requireNonNull(task, "task");
        inputs = List.copyOf(inputs);
        outputs = List.copyOf(outputs);
    }

    /**
     * Initializes {@code spec}'s task with the monitor's own setup, on a manual clock at world time
     * 0, and returns what it declared. The task's handles are never bound: use a fresh instance,
     * not one registered with a monitor, and throw it away afterwards.
     *
     * @param spec a fresh task
     * @return its declarations
     * @throws ConfigurationException if its {@code initialize} throws, or its declarations break
     *     a rule of their own (a key declared twice, a max age that is not positive), each
     *     violation a sentence as {@link Monitor.Builder#build()} reports it
     */
    public static TaskDeclaration of(TaskSpec spec) {
        DeclaringSetup setup = DeclaringSetup.initialize(Objects.requireNonNull(spec, "spec"), new ManualClock());
        if (!setup.violations.isEmpty()) {
            throw new ConfigurationException(setup.violations);
        }
        return setup.declaration();
    }
}
