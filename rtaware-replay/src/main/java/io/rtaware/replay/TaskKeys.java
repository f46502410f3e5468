package io.rtaware.replay;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.ReadStatus;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import io.rtaware.core.time.ManualClock;
import io.rtaware.core.task.TaskSetup;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * The keys a task consumes and produces, found by initializing a fresh instance of it with a
 * setup that only notes its declarations (the instance is then thrown away).
 *
 * @param task the task's name
 * @param inputs the keys it consumes, in declaration order (the order of its recorded input generations)
 * @param outputs the keys it produces
 */
record TaskKeys(String task, List<Key<?>> inputs, List<Key<?>> outputs) {

    /**
     * @param spec a fresh task, not registered anywhere
     * @return its declarations
     * @throws IllegalStateException if its initialization throws
     */
    static TaskKeys of(TaskSpec spec) {
        Probe probe = new Probe(spec.name(), spec.schedule());
        try {
            spec.task().initialize(probe);
        } catch (Exception e) {
            throw new IllegalStateException("task '" + spec.name() + "' failed to initialize: " + e, e);
        }
        return new TaskKeys(spec.name(), List.copyOf(probe.inputs), List.copyOf(probe.outputs));
    }

    /** Notes declarations; the handles it returns are never used. */
    private static final class Probe implements TaskSetup {
        private final String name;
        private final Schedule schedule;
        private final Clock clock = new ManualClock();
        final List<Key<?>> inputs = new ArrayList<>();
        final List<Key<?>> outputs = new ArrayList<>();

        Probe(String name, Schedule schedule) {
            this.name = name;
            this.schedule = schedule;
        }

        @Override
        public String taskName() {
            return name;
        }

        @Override
        public Schedule schedule() {
            return schedule;
        }

        @Override
        public Clock clock() {
            return clock;
        }

        @Override
        public <T extends StateValue<T>> Input<T> consume(Key<T> key) {
            return consume(key, null);
        }

        @Override
        public <T extends StateValue<T>> Input<T> consume(Key<T> key, Duration maxAge) {
            inputs.add(key);
            T buffer = key.newBuffer();
            return new Input<>() {
                @Override
                public Key<T> key() {
                    return key;
                }

                @Override
                public T value() {
                    return buffer;
                }

                @Override
                public ReadStatus status() {
                    return ReadStatus.NONE;
                }

                @Override
                public long ageNs() {
                    return Long.MAX_VALUE;
                }

                @Override
                public long generation() {
                    return 0;
                }

                @Override
                public long maxAgeNs() {
                    return maxAge == null ? Long.MAX_VALUE : maxAge.toNanos();
                }
            };
        }

        @Override
        public <T extends StateValue<T>> Output<T> produce(Key<T> key) {
            outputs.add(key);
            T buffer = key.newBuffer();
            return new Output<>() {
                @Override
                public Key<T> key() {
                    return key;
                }

                @Override
                public T value() {
                    return buffer;
                }

                @Override
                public void publish() {
                }

                @Override
                public long commits() {
                    return 0;
                }
            };
        }
    }
}
