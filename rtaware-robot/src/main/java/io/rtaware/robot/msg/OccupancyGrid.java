package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * A tri-state occupancy grid map (after ROS {@code nav_msgs/OccupancyGrid}): each cell is
 * {@link #UNKNOWN}, {@link #FREE} or {@link #OCCUPIED}. Cell {@code (cx, cy)} covers
 * {@code [originXM + cx * resolutionM, originXM + (cx + 1) * resolutionM)} in x and likewise in
 * y, and is stored at index {@code cy * width + cx} (row 0 is the lowest y). Fixed capacity,
 * mutable buffer for the data store; {@link #copyFrom} copies the cells without allocating.
 * Not thread-safe.
 */
public final class OccupancyGrid implements StateValue<OccupancyGrid> {

    /** Cell value: never observed. */
    public static final byte UNKNOWN = -1;
    /** Cell value: observed open. */
    public static final byte FREE = 0;
    /** Cell value: observed occupied. */
    public static final byte OCCUPIED = 100;

    /** Default capacity in cells: a 20 m x 20 m area at 0.05 m. */
    public static final int DEFAULT_CAPACITY = 400 * 400;

    /** world x of the grid's lower-left corner in metres. */
    public double originXM;
    /** world y of the grid's lower-left corner in metres. */
    public double originYM;
    /** edge length of a cell in metres (0 while empty). */
    public double resolutionM;
    /** how many scans have been integrated into this map. */
    public long scansIntegrated;
    /** cell values; only the first {@code width * height} are valid. */
    public final byte[] cells;
    private int width;
    private int height;

    /** An empty grid with {@link #DEFAULT_CAPACITY} cells of capacity. */
    public OccupancyGrid() {
        this(DEFAULT_CAPACITY);
    }

    /** @param capacityCells maximum number of cells */
    public OccupancyGrid(int capacityCells) {
        this.cells = new byte[capacityCells];
    }

    /**
     * Sets the geometry; cells keep their values.
     *
     * @param widthCells cells along x
     * @param heightCells cells along y
     * @param resolution cell edge in metres
     * @param originX world x of the lower-left corner in metres
     * @param originY world y of the lower-left corner in metres
     * @throws IllegalArgumentException if the size is negative or exceeds the capacity
     */
    public void setGeometry(int widthCells, int heightCells, double resolution, double originX, double originY) {
        if (widthCells < 0 || heightCells < 0 || (long) widthCells * heightCells > cells.length) {
            throw new IllegalArgumentException("grid " + widthCells + " x " + heightCells
                    + " exceeds capacity " + cells.length + " cells");
        }
        this.width = widthCells;
        this.height = heightCells;
        this.resolutionM = resolution;
        this.originXM = originX;
        this.originYM = originY;
    }

    /** @return cells along x */
    public int width() {
        return width;
    }

    /** @return cells along y */
    public int height() {
        return height;
    }

    /** @return true if no geometry was set (nothing published yet) */
    public boolean isEmpty() {
        return width == 0 || height == 0;
    }

    /**
     * @param cx cell column
     * @param cy cell row
     * @return the cell's value, {@link #UNKNOWN} outside the grid
     */
    public byte cell(int cx, int cy) {
        if (cx < 0 || cy < 0 || cx >= width || cy >= height) {
            return UNKNOWN;
        }
        return cells[cy * width + cx];
    }

    /**
     * @param xM world x in metres
     * @return the column containing it (may be outside the grid)
     */
    public int cellX(double xM) {
        return (int) Math.floor((xM - originXM) / resolutionM);
    }

    /**
     * @param yM world y in metres
     * @return the row containing it (may be outside the grid)
     */
    public int cellY(double yM) {
        return (int) Math.floor((yM - originYM) / resolutionM);
    }

    /**
     * @param cx a column
     * @return world x of the column's centre in metres
     */
    public double centerXM(int cx) {
        return originXM + (cx + 0.5) * resolutionM;
    }

    /**
     * @param cy a row
     * @return world y of the row's centre in metres
     */
    public double centerYM(int cy) {
        return originYM + (cy + 0.5) * resolutionM;
    }

    @Override
    public void copyFrom(OccupancyGrid s) {
        setGeometry(s.width, s.height, s.resolutionM, s.originXM, s.originYM);
        scansIntegrated = s.scansIntegrated;
        System.arraycopy(s.cells, 0, cells, 0, s.width * s.height);
    }
}
