package io.rtaware.live;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;

/**
 * A test task that spins for a fixed wall time each cycle and publishes a counter on
 * {@code <name>.out} (one more than the upstream task's, when it has one), so the live view
 * has tasks, keys, producers and consumers to show.
 */
final class ChainTask implements Task {

    /** The value on a chain task's key. */
    static final class Count implements StateValue<Count> {
        long value;

        @Override
        public void copyFrom(Count source) {
            value = source.value;
        }
    }

    private final String name;
    private final long spinNs;
    private final String upstream;
    private Input<Count> input;
    private Output<Count> output;

    /**
     * @param name the task's name; its key is {@code name + ".out"}
     * @param spinNs wall time to spin per cycle
     * @param upstream the task whose output this one consumes, or null
     */
    ChainTask(String name, long spinNs, String upstream) {
        this.name = name;
        this.spinNs = spinNs;
        this.upstream = upstream;
    }

    private static Key<Count> key(String task) {
        return Key.of(task + ".out", Count.class, Count::new);
    }

    @Override
    public void initialize(TaskSetup setup) {
        output = setup.produce(key(name));
        if (upstream != null) {
            input = setup.consume(key(upstream));
        }
    }

    @Override
    public void execute(long nowNs) {
        long start = System.nanoTime();
        while (System.nanoTime() - start < spinNs) {
            Thread.onSpinWait();
        }
        output.value().value = (input == null ? output.value().value : input.value().value) + 1;
        output.publish();
    }
}
