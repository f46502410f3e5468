package io.rtaware.nav.testing;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.ReadStatus;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.Clock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A single-threaded stand-in for the core's data store and task setup, for tests: latest-value
 * slots by key name, inputs copied at {@link Bound#before}, outputs committed at
 * {@link Bound#after}, with generations and commit times like the real store.
 */
public final class FakeStore {

    private final Map<String, Slot<?>> slots = new HashMap<>();

    private static final class Slot<T extends StateValue<T>> {
        final T value;
        long generation;
        long commitNs;

        Slot(Key<T> key) {
            this.value = key.newBuffer();
        }
    }

    @SuppressWarnings("unchecked")
    private <T extends StateValue<T>> Slot<T> slot(Key<T> key) {
        return (Slot<T>) slots.computeIfAbsent(key.name(), n -> new Slot<>(key));
    }

    /**
     * Commits a value directly, as a producer outside the tasks would.
     *
     * @param key the key
     * @param value the value (copied)
     * @param nowNs commit time
     * @param <T> the type
     */
    public <T extends StateValue<T>> void write(Key<T> key, T value, long nowNs) {
        Slot<T> s = slot(key);
        s.value.copyFrom(value);
        s.generation++;
        s.commitNs = nowNs;
    }

    /**
     * @param key the key
     * @param <T> the type
     * @return the stored value (live; do not modify)
     */
    public <T extends StateValue<T>> T read(Key<T> key) {
        return slot(key).value;
    }

    /**
     * @param key the key
     * @return commits so far
     */
    public long generation(Key<?> key) {
        Slot<?> s = slots.get(key.name());
        return s == null ? 0 : s.generation;
    }

    /**
     * Initializes a task against this store.
     *
     * @param name task name
     * @param task the task
     * @return the bound task
     * @throws Exception if initialization fails
     */
    public Bound bind(String name, Task task) throws Exception {
        Bound b = new Bound(name, task);
        task.initialize(b);
        return b;
    }

    /** A task bound to the store: its setup, inputs and outputs. */
    public final class Bound implements TaskSetup {
        private final String name;
        private final Task task;
        private final List<FakeInput<?>> inputs = new ArrayList<>();
        private final List<FakeOutput<?>> outputs = new ArrayList<>();

        private Bound(String name, Task task) {
            this.name = name;
            this.task = task;
        }

        /**
         * One cycle: copy inputs, execute, commit published outputs.
         *
         * @param nowNs world time
         * @throws Exception from the task
         */
        public void cycle(long nowNs) throws Exception {
            before(nowNs);
            task.execute(nowNs);
            after(nowNs);
        }

        /** @param nowNs world time; refreshes the inputs */
        public void before(long nowNs) {
            for (FakeInput<?> in : inputs) {
                in.refresh(nowNs);
            }
        }

        /** @param nowNs world time; commits published outputs */
        public void after(long nowNs) {
            for (FakeOutput<?> out : outputs) {
                out.commitIfPublished(nowNs);
            }
        }

        @Override
        public String taskName() {
            return name;
        }

        @Override
        public Schedule schedule() {
            return Schedule.continuous();
        }

        @Override
        public Clock clock() {
            throw new UnsupportedOperationException("no clock in tests");
        }

        @Override
        public <T extends StateValue<T>> Input<T> consume(Key<T> key) {
            return consume(key, null);
        }

        @Override
        public <T extends StateValue<T>> Input<T> consume(Key<T> key, Duration maxAge) {
            FakeInput<T> in = new FakeInput<>(slot(key), key, maxAge == null ? Long.MAX_VALUE : maxAge.toNanos());
            inputs.add(in);
            return in;
        }

        @Override
        public <T extends StateValue<T>> Output<T> produce(Key<T> key) {
            FakeOutput<T> out = new FakeOutput<>(slot(key), key);
            outputs.add(out);
            return out;
        }
    }

    private static final class FakeInput<T extends StateValue<T>> implements Input<T> {
        private final Slot<T> slot;
        private final Key<T> key;
        private final T value;
        private final long maxAgeNs;
        private long held;
        private long ageNs = Long.MAX_VALUE;
        private ReadStatus status = ReadStatus.NONE;

        FakeInput(Slot<T> slot, Key<T> key, long maxAgeNs) {
            this.slot = slot;
            this.key = key;
            this.value = key.newBuffer();
            this.maxAgeNs = maxAgeNs;
        }

        void refresh(long nowNs) {
            if (slot.generation == 0) {
                status = ReadStatus.NONE;
                ageNs = Long.MAX_VALUE;
                return;
            }
            if (slot.generation != held) {
                value.copyFrom(slot.value);
                held = slot.generation;
                status = ReadStatus.NEW;
            } else {
                status = ReadStatus.OLD;
            }
            ageNs = nowNs - slot.commitNs;
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
            return status;
        }

        @Override
        public long ageNs() {
            return ageNs;
        }

        @Override
        public long generation() {
            return held;
        }

        @Override
        public long maxAgeNs() {
            return maxAgeNs;
        }
    }

    private static final class FakeOutput<T extends StateValue<T>> implements Output<T> {
        private final Slot<T> slot;
        private final Key<T> key;
        private final T value;
        private boolean published;
        private long commits;

        FakeOutput(Slot<T> slot, Key<T> key) {
            this.slot = slot;
            this.key = key;
            this.value = key.newBuffer();
        }

        void commitIfPublished(long nowNs) {
            if (published) {
                slot.value.copyFrom(value);
                slot.generation++;
                slot.commitNs = nowNs;
                commits++;
                published = false;
            }
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
            published = true;
        }

        @Override
        public long commits() {
            return commits;
        }
    }
}
