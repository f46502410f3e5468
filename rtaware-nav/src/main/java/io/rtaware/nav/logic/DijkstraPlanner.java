package io.rtaware.nav.logic;

import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.PlannedPath;

/**
 * Dijkstra's shortest path on an occupancy grid, 8-connected, from the robot's cell to the
 * closest of several goals (closest by path cost: the search stops at the first goal cell it
 * settles).
 *
 * <p>Costs: a move costs its length in metres (one cell edge, or {@code sqrt 2} of it on a
 * diagonal) times the factor of the cell entered: 1 for open cells, {@code unknownCostFactor}
 * for unknown cells, {@link #INFLATED_COST_FACTOR} for inflated cells entered from other
 * inflated cells. Occupied cells are never entered. Cells within {@code inflationRadiusM} of an
 * occupied cell are inflated: they cannot be entered from a cell that is not inflated, so that
 * a path keeps the robot's body clear of obstacles, but a robot that already stands in one may
 * drive out through them. A goal cell may always be entered. A diagonal move is allowed only if
 * both cells it cuts the corner of could be entered.
 *
 * <p>Working memory (about 30 bytes per cell) is allocated at construction for a maximum
 * number of cells; a plan allocates nothing. Cost: proportional to the cells settled before the
 * closest goal, times the log of the open set.
 *
 * <p>Not thread-safe.
 */
public final class DijkstraPlanner {

    /** Cost factor of moving through inflated cells when escaping them. */
    public static final double INFLATED_COST_FACTOR = 10.0;

    private static final byte FREE = 0;
    private static final byte UNKNOWN = 1;
    private static final byte INFLATED = 2;
    private static final byte OCCUPIED = 3;
    private static final double SQRT2 = Math.sqrt(2.0);
    private static final int[] DX = {1, -1, 0, 0, 1, 1, -1, -1};
    private static final int[] DY = {0, 0, 1, -1, 1, -1, 1, -1};

    private final int capacity;
    private final double inflationRadiusM;
    private final double unknownCostFactor;
    private final byte[] cls;
    private final double[] dist;
    private final int[] parent;
    private final int[] seenStamp;
    private final int[] closedStamp;
    private final int[] goalStamp;
    private final int[] goalSlot;
    private final int[] pathCells;
    private final IndexedMinHeap heap;
    private int stamp;

    private int width;
    private int height;
    private double resolutionM;
    private double originXM;
    private double originYM;
    private int[] inflationDx = new int[0];
    private int[] inflationDy = new int[0];
    private double inflationForResolutionM = -1;
    private long settledLastPlan;

    /**
     * @param capacityCells the largest map, in cells
     * @param inflationRadiusM robot radius plus safety margin, in metres
     * @param unknownCostFactor cost factor of unknown cells, at least 1
     * @throws IllegalArgumentException naming the bad value
     */
    public DijkstraPlanner(int capacityCells, double inflationRadiusM, double unknownCostFactor) {
        if (capacityCells <= 0) {
            throw new IllegalArgumentException("capacityCells must be > 0, got " + capacityCells);
        }
        if (!(inflationRadiusM >= 0) || Double.isInfinite(inflationRadiusM)) {
            throw new IllegalArgumentException("inflationRadiusM must be >= 0, got " + inflationRadiusM);
        }
        if (!(unknownCostFactor >= 1) || Double.isInfinite(unknownCostFactor)) {
            throw new IllegalArgumentException("unknownCostFactor must be >= 1, got " + unknownCostFactor);
        }
        this.capacity = capacityCells;
        this.inflationRadiusM = inflationRadiusM;
        this.unknownCostFactor = unknownCostFactor;
        this.cls = new byte[capacityCells];
        this.dist = new double[capacityCells];
        this.parent = new int[capacityCells];
        this.seenStamp = new int[capacityCells];
        this.closedStamp = new int[capacityCells];
        this.goalStamp = new int[capacityCells];
        this.goalSlot = new int[capacityCells];
        this.pathCells = new int[capacityCells];
        this.heap = new IndexedMinHeap(capacityCells);
    }

    /**
     * Takes a new map: classifies its cells and inflates its obstacles. The inflation offsets
     * are recomputed (allocating) only when the resolution changes.
     *
     * @param map the map
     * @throws IllegalArgumentException if the map has more cells than the capacity
     */
    public void setMap(OccupancyGrid map) {
        int n = map.width() * map.height();
        if (n > capacity) {
            throw new IllegalArgumentException("map of " + n + " cells exceeds planner capacity " + capacity);
        }
        width = map.width();
        height = map.height();
        resolutionM = map.resolutionM;
        originXM = map.originXM;
        originYM = map.originYM;
        if (resolutionM != inflationForResolutionM) {
            computeInflationOffsets();
        }
        byte[] cells = map.cells;
        for (int i = 0; i < n; i++) {
            byte c = cells[i];
            cls[i] = c == OccupancyGrid.OCCUPIED ? OCCUPIED : c == OccupancyGrid.FREE ? FREE : UNKNOWN;
        }
        int k = inflationDx.length;
        for (int cy = 0; cy < height; cy++) {
            int row = cy * width;
            for (int cx = 0; cx < width; cx++) {
                if (cells[row + cx] != OccupancyGrid.OCCUPIED) {
                    continue;
                }
                for (int j = 0; j < k; j++) {
                    int x = cx + inflationDx[j];
                    int y = cy + inflationDy[j];
                    if (x >= 0 && y >= 0 && x < width && y < height) {
                        int idx = y * width + x;
                        if (cls[idx] < INFLATED) {
                            cls[idx] = INFLATED;
                        }
                    }
                }
            }
        }
    }

    /** @return cells settled by the last plan (its work) */
    public long settledLastPlan() {
        return settledLastPlan;
    }

    /**
     * Plans from a position to the closest goal of a registry.
     *
     * @param startXM start x in metres
     * @param startYM start y in metres
     * @param goals the goals; those outside the map are ignored
     * @param out receives the path (points from the start cell's centre to the goal's exact
     *     position, subsampled evenly if longer than its capacity); marked invalid if there is
     *     no map, no goal, the start is outside the map or no goal can be reached
     * @return true if a path was found
     */
    public boolean plan(double startXM, double startYM, GoalRegistry goals, PlannedPath out) {
        out.clear();
        settledLastPlan = 0;
        if (width == 0 || goals.count() == 0) {
            return false;
        }
        int sx = cellX(startXM);
        int sy = cellY(startYM);
        if (!inside(sx, sy)) {
            return false;
        }
        nextStamp();
        boolean anyGoal = false;
        for (int g = 0; g < goals.count(); g++) {
            int gx = cellX(goals.xM(g));
            int gy = cellY(goals.yM(g));
            if (inside(gx, gy)) {
                int idx = gy * width + gx;
                if (goalStamp[idx] != stamp) {
                    goalStamp[idx] = stamp;
                    goalSlot[idx] = g;
                    anyGoal = true;
                }
            }
        }
        if (!anyGoal) {
            return false;
        }
        int start = sy * width + sx;
        seenStamp[start] = stamp;
        dist[start] = 0;
        parent[start] = -1;
        heap.clear();
        heap.insertOrDecrease(start, 0);
        int found = -1;
        while (!heap.isEmpty()) {
            int u = heap.poll();
            closedStamp[u] = stamp;
            settledLastPlan++;
            if (goalStamp[u] == stamp) {
                found = u;
                break;
            }
            int ux = u % width;
            int uy = u / width;
            boolean fromInflated = u == start || cls[u] >= INFLATED;
            double du = dist[u];
            for (int d = 0; d < 8; d++) {
                int vx = ux + DX[d];
                int vy = uy + DY[d];
                if (!inside(vx, vy)) {
                    continue;
                }
                int v = vy * width + vx;
                if (closedStamp[v] == stamp || !enterable(v, fromInflated)) {
                    continue;
                }
                double step = resolutionM;
                if (d >= 4) {
                    if (!enterable(uy * width + vx, fromInflated) || !enterable(vy * width + ux, fromInflated)) {
                        continue;
                    }
                    step *= SQRT2;
                }
                double dv = du + step * costFactor(v);
                if (seenStamp[v] != stamp || dv < dist[v]) {
                    seenStamp[v] = stamp;
                    dist[v] = dv;
                    parent[v] = u;
                    heap.insertOrDecrease(v, dv);
                }
            }
        }
        heap.clear();
        if (found < 0) {
            return false;
        }
        writePath(found, goals, goalSlot[found], out);
        return true;
    }

    private boolean enterable(int v, boolean fromInflated) {
        if (goalStamp[v] == stamp) {
            return true;
        }
        byte c = cls[v];
        return c < INFLATED || (c == INFLATED && fromInflated);
    }

    private double costFactor(int v) {
        return switch (cls[v]) {
            case FREE -> 1.0;
            case UNKNOWN -> unknownCostFactor;
            default -> INFLATED_COST_FACTOR;
        };
    }

    private void writePath(int goalCell, GoalRegistry goals, int slot, PlannedPath out) {
        int length = 0;
        for (int c = goalCell; c >= 0; c = parent[c]) {
            pathCells[length++] = c;
        }
        // pathCells holds goal..start; write start..goal, subsampled evenly if too long.
        int points = Math.min(length, out.capacity());
        out.setCount(points);
        for (int i = 0; i < points; i++) {
            int fromStart = points == length || points < 2 ? i : (int) ((long) i * (length - 1) / (points - 1));
            int c = pathCells[length - 1 - fromStart];
            out.xM[i] = originXM + (c % width + 0.5) * resolutionM;
            out.yM[i] = originYM + (c / width + 0.5) * resolutionM;
        }
        out.xM[points - 1] = goals.xM(slot);
        out.yM[points - 1] = goals.yM(slot);
        out.valid = true;
        out.goalXM = goals.xM(slot);
        out.goalYM = goals.yM(slot);
        out.goalId = goals.id(slot);
        out.requesterIndex = goals.requester(slot);
        out.costM = dist[goalCell];
    }

    private void computeInflationOffsets() {
        int r = (int) Math.ceil(inflationRadiusM / resolutionM);
        double r2 = inflationRadiusM * inflationRadiusM + 1e-12;
        int n = 0;
        for (int dy = -r; dy <= r; dy++) {
            for (int dx = -r; dx <= r; dx++) {
                if ((dx * dx + dy * dy) * resolutionM * resolutionM <= r2) {
                    n++;
                }
            }
        }
        inflationDx = new int[n];
        inflationDy = new int[n];
        int i = 0;
        for (int dy = -r; dy <= r; dy++) {
            for (int dx = -r; dx <= r; dx++) {
                if ((dx * dx + dy * dy) * resolutionM * resolutionM <= r2) {
                    inflationDx[i] = dx;
                    inflationDy[i] = dy;
                    i++;
                }
            }
        }
        inflationForResolutionM = resolutionM;
    }

    private void nextStamp() {
        stamp++;
        if (stamp == Integer.MAX_VALUE) {
            java.util.Arrays.fill(seenStamp, 0);
            java.util.Arrays.fill(closedStamp, 0);
            java.util.Arrays.fill(goalStamp, 0);
            stamp = 1;
        }
    }

    private boolean inside(int cx, int cy) {
        return cx >= 0 && cy >= 0 && cx < width && cy < height;
    }

    private int cellX(double xM) {
        return (int) Math.floor((xM - originXM) / resolutionM);
    }

    private int cellY(double yM) {
        return (int) Math.floor((yM - originYM) / resolutionM);
    }
}
