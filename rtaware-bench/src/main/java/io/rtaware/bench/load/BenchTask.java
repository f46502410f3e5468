package io.rtaware.bench.load;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;

/**
 * A synthetic task: burns a fixed amount of CPU each cycle and publishes a sample on
 * {@code <name>.out}; in a chain it also consumes the previous task's output, so stale runs and
 * feed rates show up. Allocates nothing per cycle. Run by one thread at a time.
 */
public final class BenchTask implements Task {

    private final String name;
    private final long workNs;
    private final String upstream;
    private final BusyWork work;
    private Input<BenchSample> input;
    private Output<BenchSample> output;

    /**
     * @param name the task's name; its output key is {@code name + ".out"}
     * @param workNs CPU work per cycle in wall nanoseconds
     * @param upstream the task whose output this one consumes, or null
     * @param work the calibrated busy loop
     */
    public BenchTask(String name, long workNs, String upstream, BusyWork work) {
        this.name = name;
        this.workNs = workNs;
        this.upstream = upstream;
        this.work = work;
    }

    /**
     * @param task a bench task's name
     * @return the key it produces
     */
    public static Key<BenchSample> outputKey(String task) {
        return Key.of(task + ".out", BenchSample.class, BenchSample::new);
    }

    @Override
    public void initialize(TaskSetup setup) {
        output = setup.produce(outputKey(name));
        if (upstream != null) {
            input = setup.consume(outputKey(upstream));
        }
    }

    @Override
    public void execute(long nowNs) {
        work.burn(workNs);
        output.value().sequence++;
        output.publish();
    }
}
