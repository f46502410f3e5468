package io.rtaware.core.monitor;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.ReactionConstraint;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * What one task declares during its initialization: the {@link TaskSetup} it is handed. Records
 * the task's input and output handles (unbound until the graph is built) and every violation of
 * its own declarations; closed after {@code initialize} returns. The one way a task's
 * declarations are read: by the monitor when it builds, and by {@link TaskDeclaration#of}.
 * Not thread-safe.
 */
final class DeclaringSetup implements TaskSetup {

    final TaskSpec spec;
    private final Clock clock;
    final List<InputHandle<?>> inputs = new ArrayList<>();
    final List<OutputHandle<?>> outputs = new ArrayList<>();
    final List<String> violations = new ArrayList<>();
    private ReactionConstraint reaction;
    private boolean closed;

    private DeclaringSetup(TaskSpec spec, Clock clock) {
        this.spec = spec;
        this.clock = clock;
    }

    /**
     * Initializes a task with a setup of its own and closes the setup: a task whose
     * {@code initialize} throws has that as its first violation.
     *
     * @param spec the task
     * @param clock the world clock it runs on
     * @return what it declared
     */
    static DeclaringSetup initialize(TaskSpec spec, Clock clock) {
        DeclaringSetup declarations = new DeclaringSetup(spec, clock);
        try {
            spec.task().initialize(declarations);
        } catch (Exception e) {
            declarations.violations.add(0, "task '" + spec.name() + "' failed to initialize: "
                    + e.getClass().getSimpleName() + (e.getMessage() == null ? "" : ": " + e.getMessage()));
        }
        declarations.close();
        return declarations;
    }

    /** @return the declarations as the public, immutable view */
    TaskDeclaration declaration() {
        List<TaskDeclaration.DeclaredInput> in = new ArrayList<>();
        for (InputHandle<?> handle : inputs) {
            in.add(new TaskDeclaration.DeclaredInput(handle.key(), handle.maxAgeNs()));
        }
        List<Key<?>> out = new ArrayList<>();
        for (OutputHandle<?> handle : outputs) {
            out.add(handle.key());
        }
        return new TaskDeclaration(spec.name(), in, out, reaction);
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
    public void declareReaction(ReactionConstraint constraint) {
        checkOpen();
        reaction = Objects.requireNonNull(constraint, "constraint");
    }

    /** @return the reaction the task declared, or null */
    ReactionConstraint reaction() {
        return reaction;
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
