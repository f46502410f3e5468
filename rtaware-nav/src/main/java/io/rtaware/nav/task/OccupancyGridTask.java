package io.rtaware.nav.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.nav.logic.LogOddsGrid;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.core.data.Key;
import java.time.Duration;
import java.util.Optional;

/**
 * OccupancyGridMapping ({@code occupancy}): consumes {@code laser} and {@code odometry},
 * integrates each new scan at the current pose into a log-odds grid and publishes the
 * classified grid on {@code map}. Scans or poses older than their maximum age are not
 * integrated (a wrong pose would corrupt the map); a cycle with no new scan publishes nothing.
 * On termination it keeps a copy of the grid for the run's outputs ({@link #finalMap()}).
 *
 * <p>Run by one thread at a time; {@link #finalMap()} is thread-safe.
 */
public final class OccupancyGridTask implements Task {

    private final Key<OccupancyGrid> mapKey;
    private final LogOddsGrid grid;
    private final long laserMaxAgeNs;
    private final long odometryMaxAgeNs;
    private Input<LaserScan> laser;
    private Input<Odometry> odometry;
    private Output<OccupancyGrid> map;
    private volatile OccupancyGrid finalMap;

    /**
     * @param mapKey the key to publish on (sized for the grid)
     * @param grid the grid to maintain
     * @param laserMaxAgeNs oldest scan integrated, in world ns
     * @param odometryMaxAgeNs oldest pose used, in world ns
     */
    public OccupancyGridTask(Key<OccupancyGrid> mapKey, LogOddsGrid grid, long laserMaxAgeNs, long odometryMaxAgeNs) {
        this.mapKey = mapKey;
        this.grid = grid;
        this.laserMaxAgeNs = laserMaxAgeNs;
        this.odometryMaxAgeNs = odometryMaxAgeNs;
    }

    @Override
    public void initialize(TaskSetup setup) {
        laser = setup.consume(RobotKeys.LASER, Duration.ofNanos(laserMaxAgeNs));
        odometry = setup.consume(RobotKeys.ODOMETRY, Duration.ofNanos(odometryMaxAgeNs));
        map = setup.produce(mapKey);
    }

    @Override
    public void execute(long nowNs) {
        if (!laser.isNew() || laser.isExpired() || !odometry.hasValue() || odometry.isExpired()) {
            return;
        }
        Odometry pose = odometry.value();
        grid.integrate(laser.value(), pose.xM, pose.yM, pose.yawRad);
        grid.exportTo(map.value());
        map.publish();
    }

    /** Keeps a copy of the grid for {@link #finalMap()}; allocates once. */
    @Override
    public void terminate() {
        OccupancyGrid copy = new OccupancyGrid(grid.width() * grid.height());
        grid.exportTo(copy);
        finalMap = copy;
    }

    /**
     * @return the grid as it was when the task terminated, or empty before termination
     */
    public Optional<OccupancyGrid> finalMap() {
        return Optional.ofNullable(finalMap);
    }
}
