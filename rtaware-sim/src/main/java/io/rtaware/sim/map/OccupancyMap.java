package io.rtaware.sim.map;

import io.rtaware.robot.msg.OccupancyGrid;
import java.util.Objects;

/**
 * A 2D occupancy grid in world coordinates, with a precomputed distance field.
 *
 * <p>Cell {@code (col, row)} covers x in {@code [originX + col*res, originX + (col+1)*res)}
 * and y in {@code [originY + row*res, originY + (row+1)*res)}; row 0 is the bottom (lowest
 * y), i.e. the last row of the image the map was loaded from. Only {@link CellState#OCCUPIED}
 * cells are obstacles; unknown cells are treated as free space. Everything outside the grid
 * counts as an obstacle, so a robot cannot leave the map.
 *
 * <p>The distance field holds, per cell, the Euclidean distance in metres from the cell's
 * centre to the centre of the nearest occupied cell (exact, computed with the
 * Felzenszwalb-Huttenlocher transform). Immutable after construction and thread-safe.
 */
public final class OccupancyMap {

    /** The state of one grid cell. */
    public enum CellState {
        /** no obstacle. */
        FREE,
        /** an obstacle. */
        OCCUPIED,
        /** between the free and the occupied threshold; treated as free. */
        UNKNOWN
    }

    private static final float FAR = 1e9f;

    private final int widthCells;
    private final int heightCells;
    private final double resolutionM;
    private final double originXM;
    private final double originYM;
    private final byte[] cells;
    private final float[] distanceM;
    private final String source;

    /**
     * @param source where the map came from (file name), for messages
     * @param widthCells number of columns, positive
     * @param heightCells number of rows, positive
     * @param resolutionM cell edge length in metres, positive
     * @param originXM x of the lower-left corner of cell (0, 0) in metres
     * @param originYM y of the lower-left corner of cell (0, 0) in metres
     * @param states cell states, row-major with row 0 at the bottom; copied
     * @throws IllegalArgumentException if sizes do not match or values are out of range
     */
    public OccupancyMap(String source, int widthCells, int heightCells, double resolutionM,
                        double originXM, double originYM, CellState[] states) {
        this.source = Objects.requireNonNull(source, "source");
        if (widthCells <= 0 || heightCells <= 0) {
            throw new IllegalArgumentException(source + ": map size must be positive, got "
                    + widthCells + "x" + heightCells);
        }
        if (!(resolutionM > 0) || Double.isInfinite(resolutionM)) {
            throw new IllegalArgumentException(source + ": resolution must be positive, got " + resolutionM);
        }
        if (!Double.isFinite(originXM) || !Double.isFinite(originYM)) {
            throw new IllegalArgumentException(source + ": origin must be finite, got ["
                    + originXM + ", " + originYM + "]");
        }
        if (states.length != widthCells * heightCells) {
            throw new IllegalArgumentException(source + ": " + states.length + " cells for a "
                    + widthCells + "x" + heightCells + " map");
        }
        this.widthCells = widthCells;
        this.heightCells = heightCells;
        this.resolutionM = resolutionM;
        this.originXM = originXM;
        this.originYM = originYM;
        this.cells = new byte[states.length];
        for (int i = 0; i < states.length; i++) {
            cells[i] = (byte) states[i].ordinal();
        }
        this.distanceM = computeDistanceField();
    }

    /** @return where the map came from, for messages */
    public String source() {
        return source;
    }

    /** @return number of columns */
    public int widthCells() {
        return widthCells;
    }

    /** @return number of rows */
    public int heightCells() {
        return heightCells;
    }

    /** @return cell edge length in metres */
    public double resolutionM() {
        return resolutionM;
    }

    /** @return x of the map's lower-left corner in metres */
    public double originXM() {
        return originXM;
    }

    /** @return y of the map's lower-left corner in metres */
    public double originYM() {
        return originYM;
    }

    /** @return width of the map in metres */
    public double widthM() {
        return widthCells * resolutionM;
    }

    /** @return height of the map in metres */
    public double heightM() {
        return heightCells * resolutionM;
    }

    /**
     * @param xM x in metres
     * @return the column containing x (may be outside the grid)
     */
    public int colOf(double xM) {
        return (int) Math.floor((xM - originXM) / resolutionM);
    }

    /**
     * @param yM y in metres
     * @return the row containing y (may be outside the grid)
     */
    public int rowOf(double yM) {
        return (int) Math.floor((yM - originYM) / resolutionM);
    }

    /**
     * @param col column
     * @param row row (0 = bottom)
     * @return true if the cell is inside the grid
     */
    public boolean inside(int col, int row) {
        return col >= 0 && row >= 0 && col < widthCells && row < heightCells;
    }

    /**
     * @param col column
     * @param row row (0 = bottom)
     * @return the cell's state; {@link CellState#OCCUPIED} outside the grid
     */
    public CellState state(int col, int row) {
        return inside(col, row) ? CellState.values()[cells[row * widthCells + col]] : CellState.OCCUPIED;
    }

    /**
     * @param col column
     * @param row row (0 = bottom)
     * @return true if the cell is an obstacle or outside the grid
     */
    public boolean isObstacle(int col, int row) {
        return !inside(col, row) || cells[row * widthCells + col] == 1;
    }

    /**
     * @param xM x in metres
     * @param yM y in metres
     * @return true if the point lies in an obstacle cell or outside the map
     */
    public boolean isObstacleAt(double xM, double yM) {
        return isObstacle(colOf(xM), rowOf(yM));
    }

    /**
     * @return the same walls as the robot's occupancy grid type (the live view's world, a
     *     simulator's {@code /map}): obstacles occupied, the rest free, same geometry
     */
    public OccupancyGrid toGrid() {
        OccupancyGrid grid = new OccupancyGrid(widthCells * heightCells());
        grid.setGeometry(widthCells, heightCells(), resolutionM(), originXM(), originYM());
        for (int row = 0; row < heightCells(); row++) {
            for (int col = 0; col < widthCells; col++) {
                grid.cells[row * widthCells + col] = isObstacle(col, row) ? OccupancyGrid.OCCUPIED : OccupancyGrid.FREE;
            }
        }
        return grid;
    }

    /**
     * @param col column
     * @param row row (0 = bottom)
     * @return distance in metres from the cell's centre to the nearest obstacle cell's centre;
     *     0 outside the grid
     */
    public double distanceCells(int col, int row) {
        return inside(col, row) ? distanceM[row * widthCells + col] : 0.0;
    }

    /**
     * Exact clearance of a point: the distance from it to the nearest obstacle cell (as a
     * filled square) or to the map border, whichever is nearer, but only resolved up to
     * {@code limitM}: any clearance of at least {@code limitM} may be reported as any value
     * {@code >= limitM}. Uses the distance field, so it is O(1) far from obstacles.
     *
     * @param xM x in metres
     * @param yM y in metres
     * @param limitM the clearance beyond which the exact value does not matter
     * @return the clearance in metres (0 inside an obstacle)
     */
    public double clearanceM(double xM, double yM, double limitM) {
        int col = colOf(xM);
        int row = rowOf(yM);
        if (!inside(col, row) || cells[row * widthCells + col] == 1) {
            return 0.0;
        }
        double border = Math.min(Math.min(xM - originXM, originXM + widthM() - xM),
                Math.min(yM - originYM, originYM + heightM() - yM));
        double lowerBound = distanceM[row * widthCells + col] - resolutionM * Math.sqrt(2.0);
        if (lowerBound >= limitM) {
            return Math.min(border, lowerBound);
        }
        int reach = (int) Math.ceil(limitM / resolutionM) + 1;
        double best = Math.min(border, limitM);
        for (int r = Math.max(0, row - reach); r <= Math.min(heightCells - 1, row + reach); r++) {
            double y0 = originYM + r * resolutionM;
            double dy = yM < y0 ? y0 - yM : Math.max(0.0, yM - (y0 + resolutionM));
            if (dy >= best) {
                continue;
            }
            int base = r * widthCells;
            for (int c = Math.max(0, col - reach); c <= Math.min(widthCells - 1, col + reach); c++) {
                if (cells[base + c] != 1) {
                    continue;
                }
                double x0 = originXM + c * resolutionM;
                double dx = xM < x0 ? x0 - xM : Math.max(0.0, xM - (x0 + resolutionM));
                double d = Math.sqrt(dx * dx + dy * dy);
                if (d < best) {
                    best = d;
                }
            }
        }
        return best;
    }

    /** Raw cell states (ordinal of {@link CellState}) for {@link RayCaster}; never modified. */
    byte[] cellArray() {
        return cells;
    }

    /** Raw distance field for {@link RayCaster}; never modified. */
    float[] distanceArray() {
        return distanceM;
    }

    private float[] computeDistanceField() {
        int w = widthCells;
        int h = heightCells;
        double[] sq = new double[w * h];
        for (int i = 0; i < sq.length; i++) {
            sq[i] = cells[i] == 1 ? 0.0 : FAR;
        }
        int n = Math.max(w, h);
        double[] f = new double[n];
        double[] d = new double[n];
        int[] v = new int[n];
        double[] z = new double[n + 1];
        for (int c = 0; c < w; c++) {
            for (int r = 0; r < h; r++) {
                f[r] = sq[r * w + c];
            }
            transform1d(f, h, d, v, z);
            for (int r = 0; r < h; r++) {
                sq[r * w + c] = d[r];
            }
        }
        for (int r = 0; r < h; r++) {
            System.arraycopy(sq, r * w, f, 0, w);
            transform1d(f, w, d, v, z);
            System.arraycopy(d, 0, sq, r * w, w);
        }
        float[] out = new float[w * h];
        for (int i = 0; i < out.length; i++) {
            out[i] = (float) (Math.sqrt(sq[i]) * resolutionM);
        }
        return out;
    }

    /** Felzenszwalb-Huttenlocher 1D squared distance transform of f[0..n) into d. */
    private static void transform1d(double[] f, int n, double[] d, int[] v, double[] z) {
        int k = 0;
        v[0] = 0;
        z[0] = Double.NEGATIVE_INFINITY;
        z[1] = Double.POSITIVE_INFINITY;
        for (int q = 1; q < n; q++) {
            double s = ((f[q] + (double) q * q) - (f[v[k]] + (double) v[k] * v[k])) / (2.0 * q - 2.0 * v[k]);
            while (s <= z[k]) {
                k--;
                s = ((f[q] + (double) q * q) - (f[v[k]] + (double) v[k] * v[k])) / (2.0 * q - 2.0 * v[k]);
            }
            k++;
            v[k] = q;
            z[k] = s;
            z[k + 1] = Double.POSITIVE_INFINITY;
        }
        k = 0;
        for (int q = 0; q < n; q++) {
            while (z[k + 1] < q) {
                k++;
            }
            double dq = q - v[k];
            d[q] = dq * dq + f[v[k]];
        }
    }
}
