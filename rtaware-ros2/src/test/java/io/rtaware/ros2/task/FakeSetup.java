package io.rtaware.ros2.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.ReadStatus;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.Clock;
import java.time.Duration;
import java.util.HashMap;
import java.util.Map;

/** TaskSetup double: outputs count publishes, inputs are set by the test. */
final class FakeSetup implements TaskSetup {

    static final class FakeOutput<T extends StateValue<T>> implements Output<T> {
        final Key<T> key;
        final T value;
        int published;

        FakeOutput(Key<T> key) {
            this.key = key;
            this.value = key.newBuffer();
        }

        @Override
        public Key<T> key() {
            return key;
        }

        @Override
        public T value() {
            return value;
        }

        @Override
        public void publish() {
            published++;
        }

        @Override
        public long commits() {
            return published;
        }
    }

    static final class FakeInput<T extends StateValue<T>> implements Input<T> {
        final Key<T> key;
        final T value;
        long generation;

        FakeInput(Key<T> key) {
            this.key = key;
            this.value = key.newBuffer();
        }

        @Override
        public Key<T> key() {
            return key;
        }

        @Override
        public T value() {
            return value;
        }

        @Override
        public ReadStatus status() {
            return generation == 0 ? ReadStatus.NONE : ReadStatus.NEW;
        }

        @Override
        public long ageNs() {
            return 0;
        }

        @Override
        public long generation() {
            return generation;
        }

        @Override
        public long maxAgeNs() {
            return Long.MAX_VALUE;
        }
    }

    final Map<String, FakeOutput<?>> outputs = new HashMap<>();
    final Map<String, FakeInput<?>> inputs = new HashMap<>();

    @Override
    public String taskName() {
        return "ros2";
    }

    @Override
    public Schedule schedule() {
        return Schedule.continuous();
    }

    @Override
    public Clock clock() {
        return () -> 0L;
    }

    @Override
    public <T extends StateValue<T>> Input<T> consume(Key<T> key) {
        FakeInput<T> in = new FakeInput<>(key);
        inputs.put(key.name(), in);
        return in;
    }

    @Override
    public <T extends StateValue<T>> Input<T> consume(Key<T> key, Duration maxAge) {
        return consume(key);
    }

    @Override
    public <T extends StateValue<T>> Output<T> produce(Key<T> key) {
        FakeOutput<T> out = new FakeOutput<>(key);
        outputs.put(key.name(), out);
        return out;
    }
}
