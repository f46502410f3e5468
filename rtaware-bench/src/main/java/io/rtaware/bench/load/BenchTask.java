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
    /** Every this many cycles (0: never), the cycle burns {@link #overrunNs} more. */
    private final int overrunEvery;
    private final long overrunNs;
    private int cycles;
    private Input<BenchSample> input;
    private Output<BenchSample> output;

    /**
     * @param name the task's name; its output key is {@code name + ".out"}
     * @param workNs CPU work per cycle in wall nanoseconds
     * @param upstream the task whose output this one consumes, or null
     * @param work the calibrated busy loop
     */
    public BenchTask(String name, long workNs, String upstream, BusyWork work) {
        this(name, workNs, upstream, work, 0, 0);
    }

    private BenchTask(String name, long workNs, String upstream, BusyWork work, int overrunEvery, long overrunNs) {
        this.name = name;
        this.workNs = workNs;
        this.upstream = upstream;
        this.work = work;
        this.overrunEvery = overrunEvery;
        this.overrunNs = overrunNs;
    }

    /**
     * A task that overruns now and then, for a warm-up: the JIT then compiles the paths of a
     * missed deadline and of skipped releases before the measured run needs them (code compiled
     * without them is thrown away at the first miss, and the cycles after it run interpreted).
     *
     * @param name the task's name
     * @param workNs CPU work per cycle in wall nanoseconds
     * @param overrunNs the extra work of an overrunning cycle
     * @param every every how many cycles one overruns
     * @param work the calibrated busy loop
     * @return the task
     */
    public static BenchTask overrunning(String name, long workNs, long overrunNs, int every, BusyWork work) {
        if (every <= 0 || overrunNs <= 0) {
            throw new IllegalArgumentException("every and overrunNs must be positive, got " + every + " and " + overrunNs);
        }
        return new BenchTask(name, workNs, null, work, every, overrunNs);
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
        if (overrunEvery > 0 && ++cycles % overrunEvery == 0) {
            work.burn(overrunNs);
        }
        output.value().sequence++;
        output.publish();
    }
}
