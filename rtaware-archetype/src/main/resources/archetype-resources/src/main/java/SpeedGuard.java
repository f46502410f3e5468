package ${package};

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import java.time.Duration;

/**
 * Allows {@link #DRIVE_MPS} while the nearest obstacle is at least {@link #CLEARANCE_M} away, else 0.
 * Its freshness contract: a range older than {@link #RANGE_MAX_AGE} is not trusted, so a sensor that
 * stops publishing stops the robot, and the run's report counts the cycles that ran on stale data.
 */
public final class SpeedGuard implements Task {
    /** The speed allowed when the way is clear, m/s. */
    public static final double DRIVE_MPS = 0.3;
    /** The range below which the guard stops, metres. */
    public static final double CLEARANCE_M = 0.4;
    /** The oldest range reading the guard acts on. */
    public static final Duration RANGE_MAX_AGE = Duration.ofMillis(200);

    private Input<Quantity> nearest;
    private Output<Quantity> speed;

    @Override
    public void initialize(TaskSetup setup) {
        nearest = setup.consume(Quantity.NEAREST_M, RANGE_MAX_AGE);
        speed = setup.produce(Quantity.SPEED_MPS);
    }

    @Override
    public void execute(long nowNs) {
        boolean clear = nearest.hasValue() && !nearest.isExpired() && nearest.value().value >= CLEARANCE_M;
        speed.value().value = clear ? DRIVE_MPS : 0.0;
        speed.publish();
    }
}
