package io.rtaware.experiment;

import java.util.Objects;

/**
 * What every run of an experiment shares besides the periods: the course, the emulated machine
 * speed, the random seed, the occupancy grid's resolution and the robot.
 *
 * @param scenario {@code paper-room} or the path of a scenario file, as given to {@code run}
 * @param timeScale world time runs this many times faster than wall time
 * @param seed the seed of run 1; run j uses {@code seed + j - 1} in every set
 * @param gridResolutionM occupancy grid cell size in metres, or null for {@code run}'s default
 * @param robotSeed the seed of the robot's systematic odometry errors ({@code --robot-seed}); with
 *     one robot every run uses it, as the paper's trials all used one Koala
 * @param robots how many robots the runs are spread over ({@code --robots}, at least 1): run j
 *     uses robot seed {@code robotSeed + (j - 1) mod robots}
 */
public record RunConditions(String scenario, double timeScale, long seed, Double gridResolutionM, long robotSeed,
                            int robots) {

    /**
     * The robot seed of an experiment that does not name one (and of {@code run}): robot 4, whose
     * errors (-1.1 % distance, -1.7 % rotation, -0.0055 rad/m drift) let it finish the paper's course,
     * as the paper's Koala finished its runs (60 of 60 runs, 2026-11-26); robot 1's +7.3 % rotation
     * error smeared its occupancy grid until the planner looped: 21 of 30 runs stuck or timed out.
     */
    public static final long DEFAULT_ROBOT_SEED = 4L;

    /**
     * Conditions with one robot of the default robot seed.
     *
     * @param scenario the course
     * @param timeScale world seconds per wall second
     * @param seed the seed of run 1
     * @param gridResolutionM grid cell size, or null
     */
    public RunConditions(String scenario, double timeScale, long seed, Double gridResolutionM) {
        this(scenario, timeScale, seed, gridResolutionM, DEFAULT_ROBOT_SEED, 1);
    }

    /**
     * Validates the fields.
     *
     * @param scenario {@code paper-room} or the path of a scenario file, as given to {@code run}
     * @param timeScale world time runs this many times faster than wall time
     * @param seed the seed of run 1; run j uses {@code seed + j - 1} in every set
     * @param gridResolutionM occupancy grid cell size in metres, or null for {@code run}'s default
     * @param robotSeed the seed of the robot's systematic odometry errors
     * @param robots how many robots the runs are spread over, at least 1
     */
    public RunConditions {
        Objects.requireNonNull(scenario, "scenario");
        if (!(timeScale > 0) || Double.isInfinite(timeScale)) {
            throw new IllegalArgumentException("time scale must be positive, got " + timeScale);
        }
        if (gridResolutionM != null && !(gridResolutionM > 0)) {
            throw new IllegalArgumentException("grid resolution must be positive, got " + gridResolutionM);
        }
        if (robots < 1) {
            throw new IllegalArgumentException("robots must be at least 1, got " + robots);
        }
    }

    /**
     * @param run a run number, from 1
     * @return the seed passed to that run
     */
    public long seedOf(int run) {
        return seed + run - 1;
    }

    /**
     * @param run a run number, from 1
     * @return the robot seed passed to that run: the same for every run with one robot
     */
    public long robotSeedOf(int run) {
        return robotSeed + (run - 1) % robots;
    }

    /** @return how the runs use robots, in words, for reports */
    public String robotsInWords() {
        return robots == 1 ? "one robot (robot seed " + robotSeed + ") for every run, as the paper used one Koala"
                : "runs spread over " + robots + " robots (robot seeds " + robotSeed + ".." + (robotSeed + robots - 1)
                        + ", run j on robot seed " + robotSeed + " + (j - 1) mod " + robots + ")";
    }
}
