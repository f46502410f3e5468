package io.rtaware.core.monitor;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * What one task declares during its initialization: the {@link TaskSetup} it is handed. Records
 * the task's input and output handles (unbound until the graph is built) and every violation of
 * its own declarations; closed after {@code initialize} returns. Not thread-safe.
 */
final class TaskDeclarations implements TaskSetup {

    final TaskSpec spec;
    private final Clock clock;
    final List<InputHandle<?>> inputs = new ArrayList<>();
    final List<OutputHandle<?>> outputs = new ArrayList<>();
    final List<String> violations = new ArrayList<>();
    private boolean closed;

    TaskDeclarations(TaskSpec spec, Clock clock) {
        this.spec = spec;
        this.clock = clock;
    }

    /** No declaration is accepted after this (the task's {@code initialize} has returned). */
    void close() {
        closed = true;
    }

    @Override
    public String taskName() {
        return spec.name();
    }

    @Override
    public Schedule schedule() {
        return spec.schedule();
    }

    @Override
    public Clock clock() {
        return clock;
    }

    @Override
    public <T extends StateValue<T>> Input<T> consume(Key<T> key) {
        return addInput(key, Long.MAX_VALUE);
    }

    @Override
    public <T extends StateValue<T>> Input<T> consume(Key<T> key, Duration maxAge) {
        long maxAgeNs = maxAge.toNanos();
        if (maxAgeNs <= 0) {
            violations.add("task '" + spec.name() + "' declares max age " + maxAge + " for '" + key.name()
                    + "'; it must be positive");
        }
        return addInput(key, maxAgeNs);
    }

    private <T extends StateValue<T>> Input<T> addInput(Key<T> key, long maxAgeNs) {
        checkOpen();
        checkOnce(key);
        InputHandle<T> handle = new InputHandle<>(key, maxAgeNs);
        inputs.add(handle);
        return handle;
    }

    @Override
    public <T extends StateValue<T>> Output<T> produce(Key<T> key) {
        checkOpen();
        checkOnce(key);
        OutputHandle<T> handle = new OutputHandle<>(key);
        outputs.add(handle);
        return handle;
    }

    private void checkOnce(Key<?> key) {
        if (inputs.stream().anyMatch(i -> i.key().name().equals(key.name()))
                || outputs.stream().anyMatch(o -> o.key().name().equals(key.name()))) {
            violations.add("task '" + spec.name() + "' declares '" + key.name() + "' more than once");
        }
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("task '" + spec.name() + "' declared data after initialization");
        }
    }
}
