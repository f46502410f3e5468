package io.rtaware.experiment.report;

/**
 * A rectangle of the world, in metres.
 *
 * @param minXM west edge
 * @param minYM south edge
 * @param maxXM east edge
 * @param maxYM north edge
 */
public record WorldBounds(double minXM, double minYM, double maxXM, double maxYM) {

    /**
     * Validates the fields.
     *
     * @param minXM west edge
     * @param minYM south edge
     * @param maxXM east edge
     * @param maxYM north edge
     */
    public WorldBounds {
        if (!(maxXM > minXM) || !(maxYM > minYM)) {
            throw new IllegalArgumentException("empty bounds: x " + minXM + ".." + maxXM + ", y " + minYM + ".." + maxYM);
        }
    }

    /**
     * @param other another rectangle, or null
     * @return the smallest rectangle holding both
     */
    public WorldBounds union(WorldBounds other) {
        if (other == null) {
            return this;
        }
        return new WorldBounds(Math.min(minXM, other.minXM), Math.min(minYM, other.minYM),
                Math.max(maxXM, other.maxXM), Math.max(maxYM, other.maxYM));
    }

    /**
     * @param marginM metres added on every side
     * @return the larger rectangle
     */
    public WorldBounds grow(double marginM) {
        return new WorldBounds(minXM - marginM, minYM - marginM, maxXM + marginM, maxYM + marginM);
    }

    /** @return east-west extent, m */
    public double widthM() {
        return maxXM - minXM;
    }

    /** @return north-south extent, m */
    public double heightM() {
        return maxYM - minYM;
    }
}
