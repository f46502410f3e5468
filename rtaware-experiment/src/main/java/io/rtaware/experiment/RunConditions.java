package io.rtaware.experiment;

import java.util.Objects;

/**
 * What every run of an experiment shares besides the periods: the course, the emulated machine
 * speed, the random seed and the occupancy grid's resolution.
 *
 * @param scenario {@code paper-room} or the path of a scenario file, as given to {@code run}
 * @param timeScale world time runs this many times faster than wall time
 * @param seed the seed of run 1; run j uses {@code seed + j - 1} in every set
 * @param gridResolutionM occupancy grid cell size in metres, or null for {@code run}'s default
 */
public record RunConditions(String scenario, double timeScale, long seed, Double gridResolutionM) {

    /**
     * Validates the fields.
     *
     * @param scenario {@code paper-room} or the path of a scenario file, as given to {@code run}
     * @param timeScale world time runs this many times faster than wall time
     * @param seed the seed of run 1; run j uses {@code seed + j - 1} in every set
     * @param gridResolutionM occupancy grid cell size in metres, or null for {@code run}'s default
     */
    public RunConditions {
        Objects.requireNonNull(scenario, "scenario");
        if (!(timeScale > 0) || Double.isInfinite(timeScale)) {
            throw new IllegalArgumentException("time scale must be positive, got " + timeScale);
        }
        if (gridResolutionM != null && !(gridResolutionM > 0)) {
            throw new IllegalArgumentException("grid resolution must be positive, got " + gridResolutionM);
        }
    }

    /**
     * @param run a run number, from 1
     * @return the seed passed to that run
     */
    public long seedOf(int run) {
        return seed + run - 1;
    }
}
