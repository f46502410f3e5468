package ${package};

import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import java.util.function.LongToDoubleFunction;

/**
 * Publishes the range to the nearest obstacle once per release. The range comes from a function of
 * world time, which {@link Controller} fills with a stand-in; on a robot, read your driver here.
 */
public final class RangeSensor implements Task {
    private final LongToDoubleFunction rangeMAtNs;
    private Output<Quantity> nearest;

    /** @param rangeMAtNs the range in metres at a world time in nanoseconds */
    public RangeSensor(LongToDoubleFunction rangeMAtNs) {
        this.rangeMAtNs = rangeMAtNs;
    }

    @Override
    public void initialize(TaskSetup setup) {
        nearest = setup.produce(Quantity.NEAREST_M);
    }

    @Override
    public void execute(long nowNs) {
        nearest.value().value = rangeMAtNs.applyAsDouble(nowNs);
        nearest.publish();              // committed when the cycle returns
    }
}
