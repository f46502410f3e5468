package io.rtaware.sim.map;

/**
 * Casts rays through an {@link OccupancyMap}: sphere tracing on the distance field while far
 * from obstacles, then an exact grid traversal (Amanatides-Woo DDA) near them. The result is
 * the exact distance at which the ray enters the first obstacle cell (or leaves the map).
 * Allocation-free. Immutable and thread-safe.
 */
public final class RayCaster implements BeamCaster {

    private static final double SQRT2 = Math.sqrt(2.0);

    private final OccupancyMap map;

    /** @param map the map to cast in */
    public RayCaster(OccupancyMap map) {
        this.map = map;
    }

    /** @return the map rays are cast in */
    public OccupancyMap map() {
        return map;
    }

    /**
     * @param xM ray origin x in metres
     * @param yM ray origin y in metres
     * @param dirX x of the unit direction
     * @param dirY y of the unit direction
     * @param maxRangeM the range beyond which nothing is looked for
     * @return distance in metres to the first obstacle cell or the map edge; exactly
     *     {@code maxRangeM} if none is nearer
     */
    @Override
    public double castM(double xM, double yM, double dirX, double dirY, double maxRangeM) {
        final double res = map.resolutionM();
        final double invRes = 1.0 / res;
        final double ox = map.originXM();
        final double oy = map.originYM();
        final int w = map.widthCells();
        final int h = map.heightCells();
        final byte[] cells = map.cellArray();
        final float[] dist = map.distanceArray();
        final double margin = res * SQRT2;
        final double skipMin = 2.0 * res;
        double t = 0.0;
        while (true) {
            // Phase 1: sphere tracing on the distance field.
            int col;
            int row;
            while (true) {
                if (t >= maxRangeM) {
                    return maxRangeM;
                }
                double px = xM + dirX * t;
                double py = yM + dirY * t;
                col = (int) Math.floor((px - ox) * invRes);
                row = (int) Math.floor((py - oy) * invRes);
                if (col < 0 || row < 0 || col >= w || row >= h) {
                    return t;
                }
                int idx = row * w + col;
                if (cells[idx] == 1) {
                    return t;
                }
                double skip = dist[idx] - margin;
                if (skip <= skipMin) {
                    break;
                }
                t += skip;
            }
            // Phase 2: exact grid traversal from the current point.
            double px = xM + dirX * t;
            double py = yM + dirY * t;
            int stepX = dirX > 0 ? 1 : -1;
            int stepY = dirY > 0 ? 1 : -1;
            double tMaxX;
            double tMaxY;
            double tDeltaX;
            double tDeltaY;
            if (dirX == 0.0) {
                tMaxX = Double.POSITIVE_INFINITY;
                tDeltaX = Double.POSITIVE_INFINITY;
            } else {
                double edge = ox + (dirX > 0 ? col + 1 : col) * res;
                tMaxX = t + (edge - px) / dirX;
                tDeltaX = res / Math.abs(dirX);
            }
            if (dirY == 0.0) {
                tMaxY = Double.POSITIVE_INFINITY;
                tDeltaY = Double.POSITIVE_INFINITY;
            } else {
                double edge = oy + (dirY > 0 ? row + 1 : row) * res;
                tMaxY = t + (edge - py) / dirY;
                tDeltaY = res / Math.abs(dirY);
            }
            boolean resumeSkipping = false;
            while (!resumeSkipping) {
                if (tMaxX < tMaxY) {
                    t = tMaxX;
                    col += stepX;
                    tMaxX += tDeltaX;
                } else {
                    t = tMaxY;
                    row += stepY;
                    tMaxY += tDeltaY;
                }
                if (t >= maxRangeM) {
                    return maxRangeM;
                }
                if (col < 0 || row < 0 || col >= w || row >= h) {
                    return t;
                }
                int idx = row * w + col;
                if (cells[idx] == 1) {
                    return t;
                }
                resumeSkipping = dist[idx] - margin > 4.0 * res;
            }
        }
    }
}
