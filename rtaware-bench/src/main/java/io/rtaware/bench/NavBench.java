package io.rtaware.bench;

import io.rtaware.nav.logic.DijkstraPlanner;
import io.rtaware.nav.logic.GoalRegistry;
import io.rtaware.nav.logic.LogOddsGrid;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.PlannedPath;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Cost per cycle of the navigation behaviors' heavy steps on the paper's 9.6 m x 6.2 m room
 * with a 1 m box in it, at the paper's 0.5 m grid and the default 0.05 m grid: integrating one
 * 683-beam URG scan into the grid (what {@code occupancy} does per new scan, including the
 * export to the map message), taking a new map into the planner (classification and
 * inflation), and one Dijkstra plan from one corner of the room to the opposite corner (what
 * {@code planner} does per replan). Run:
 * {@code java -jar rtaware-bench/target/benchmarks.jar NavBench -f 1 -wi 2 -i 3}.
 * Each benchmark instance is used by one JMH thread.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class NavBench {

    private static final int BEAMS = 683;
    private static final double HALF_FOV_RAD = Math.toRadians(120);
    private static final double MAX_RANGE_M = 5.6;
    /** Room walls and a box, as rectangles: x0, y0, x1, y1. */
    private static final double[][] RECTS = {{0, 0, 9.6, 6.2}, {4.3, 2.6, 5.3, 3.6}};

    /** Grid cell edge in metres. */
    @Param({"0.5", "0.05"})
    public double resolutionM;

    private LogOddsGrid grid;
    private OccupancyGrid map;
    private DijkstraPlanner planner;
    private final GoalRegistry goals = new GoalRegistry(1, 4);
    private final PlannedPath path = new PlannedPath();
    private final LaserScan scan = new LaserScan(BEAMS);

    /** Builds a map from scans taken around the room, and the planner on it. */
    @Setup(Level.Trial)
    public void setUp() {
        int w = (int) Math.ceil(10.0 / resolutionM);
        int h = (int) Math.ceil(6.6 / resolutionM);
        grid = new LogOddsGrid(-0.2, -0.2, w, h, resolutionM);
        map = new OccupancyGrid(w * h);
        double[][] poses = {{1, 1, 0}, {8.6, 1, 1.57}, {8.6, 5.2, 3.14}, {1, 5.2, -1.57}, {4.8, 1.2, 1.0}};
        for (double[] p : poses) {
            scanFrom(p[0], p[1], p[2]);
            grid.integrate(scan, p[0], p[1], p[2]);
        }
        grid.exportTo(map);
        planner = new DijkstraPlanner(w * h, 0.25, 2.0);
        planner.setMap(map);
        goals.add(0, 1, 8.8, 5.4);
        scanFrom(2.0, 3.1, 0.0);
    }

    /** @return the map's scan count, so the work is not eliminated */
    @Benchmark
    public long gridUpdateOneScan() {
        grid.integrate(scan, 2.0, 3.1, 0.0);
        grid.exportTo(map);
        return map.scansIntegrated;
    }

    /** Classifies and inflates the map for the planner. */
    @Benchmark
    public void plannerSetMap() {
        planner.setMap(map);
    }

    /** @return the plan's cost */
    @Benchmark
    public double dijkstraPlanAcrossTheRoom() {
        planner.plan(0.6, 0.6, goals, path);
        return path.costM;
    }

    private void scanFrom(double x, double y, double yaw) {
        scan.setCount(BEAMS);
        scan.minAngleRad = -HALF_FOV_RAD;
        scan.maxAngleRad = HALF_FOV_RAD;
        scan.maxRangeM = MAX_RANGE_M;
        for (int b = 0; b < BEAMS; b++) {
            double a = yaw + scan.bearingRad(b);
            scan.rangesM[b] = (float) cast(x, y, Math.cos(a), Math.sin(a));
        }
    }

    private static double cast(double ox, double oy, double dx, double dy) {
        double best = MAX_RANGE_M;
        for (double[] r : RECTS) {
            best = Math.min(best, hitAxis(ox, dx, r[0], oy, dy, r[1], r[3]));
            best = Math.min(best, hitAxis(ox, dx, r[2], oy, dy, r[1], r[3]));
            best = Math.min(best, hitAxis(oy, dy, r[1], ox, dx, r[0], r[2]));
            best = Math.min(best, hitAxis(oy, dy, r[3], ox, dx, r[0], r[2]));
        }
        return best;
    }

    /** Distance along a ray to the line {@code u = at}, if it crosses it within {@code v in [lo, hi]}. */
    private static double hitAxis(double ou, double du, double at, double ov, double dv, double lo, double hi) {
        if (Math.abs(du) < 1e-12) {
            return Double.MAX_VALUE;
        }
        double t = (at - ou) / du;
        double v = ov + t * dv;
        return t > 0 && v >= lo && v <= hi ? t : Double.MAX_VALUE;
    }
}
