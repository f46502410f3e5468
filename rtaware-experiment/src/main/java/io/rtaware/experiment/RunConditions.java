package io.rtaware.experiment;

import io.rtaware.core.conditions.CpuQuota;
import java.util.Objects;

/**
 * What every run of an experiment shares besides the periods: the course, the emulated machine
 * speed, the seeds, the occupancy grid's resolution, the robots and the design that gives each run
 * its world seed and robot.
 *
 * @param scenario {@code paper-room} or the path of a scenario file, as given to {@code run}
 * @param timeScale world time runs this many times faster than wall time
 * @param seed the world seed of run 1 of set 1; the others follow from it by the design
 *     ({@link #seedOf(int, int)})
 * @param gridResolutionM occupancy grid cell size in metres, or null for {@code run}'s default
 * @param robotSeed the first robot seed of the population ({@code --robot-seed}): the population is
 *     robot seeds {@code robotSeed} to {@code robotSeed + robots - 1}, each one simulated robot with
 *     its own systematic odometry errors
 * @param robots the population's size ({@code --robots}, at least 1); with one robot every run
 *     drives it
 * @param design how each run gets its world seed and its robot ({@link ExperimentDesign})
 * @param cpuLimitCpus the CPU quota each run's JVM ran under ({@code --cpu-limit}: the controller
 *     and its built-in server share it, as the paper's robot ran both on one computer), or null for none
 */
public record RunConditions(String scenario, double timeScale, long seed, Double gridResolutionM, long robotSeed,
                            int robots, ExperimentDesign design, Double cpuLimitCpus) {

    /**
     * The robot seed of plans and rows that predate the robot columns: robot 4, which every
     * published folder of 2026-11-26 drove. It was picked after robot 1 got stuck or timed out in
     * 21 of 30 runs, i.e. by its outcome; new experiments draw from a population instead
     * ({@link #POPULATION_FIRST_ROBOT_SEED}, {@link #POPULATION_ROBOTS}).
     */
    public static final long DEFAULT_ROBOT_SEED = 4L;

    /** The first robot seed of the default population. */
    public static final long POPULATION_FIRST_ROBOT_SEED = 1L;

    /**
     * The default population's size: robot seeds 1 to 1000, fixed before any run, far more robots
     * than an experiment has runs, so no robot is there because of how it drove.
     */
    public static final int POPULATION_ROBOTS = 1000;

    /**
     * Blocked conditions with one robot of {@link #DEFAULT_ROBOT_SEED}: those of a folder made before
     * the robot and the design were recorded.
     *
     * @param scenario the course
     * @param timeScale world seconds per wall second
     * @param seed the seed of run 1
     * @param gridResolutionM grid cell size, or null
     */
    public RunConditions(String scenario, double timeScale, long seed, Double gridResolutionM) {
        this(scenario, timeScale, seed, gridResolutionM, DEFAULT_ROBOT_SEED, 1, ExperimentDesign.BLOCKED);
    }

    /**
     * Conditions without a CPU quota.
     *
     * @param scenario the course
     * @param timeScale world seconds per wall second
     * @param seed the world seed of set 1 run 1
     * @param gridResolutionM grid cell size, or null
     * @param robotSeed the first robot seed of the population
     * @param robots the population's size
     * @param design how each run gets its world seed and robot
     */
    public RunConditions(String scenario, double timeScale, long seed, Double gridResolutionM, long robotSeed, int robots,
                         ExperimentDesign design) {
        this(scenario, timeScale, seed, gridResolutionM, robotSeed, robots, design, null);
    }

    /**
     * @param cpus the CPU quota of each run, or null for none
     * @return these conditions with it
     */
    public RunConditions withCpuLimit(Double cpus) {
        return new RunConditions(scenario, timeScale, seed, gridResolutionM, robotSeed, robots, design, cpus);
    }

    /**
     * The conditions of {@code experiment}'s options: with neither a first robot seed nor a
     * population size, the default population ({@link #POPULATION_FIRST_ROBOT_SEED},
     * {@link #POPULATION_ROBOTS}); with a robot seed alone, that one robot for every run; with a
     * size alone, that many robots from {@link #POPULATION_FIRST_ROBOT_SEED}.
     *
     * @param scenario the course
     * @param timeScale world seconds per wall second
     * @param seed the world seed of set 1 run 1
     * @param gridResolutionM grid cell size, or null
     * @param robotSeed the first robot seed ({@code --robot-seed}), or null if not given
     * @param robots the population's size ({@code --robots}), or null if not given
     * @param design how each run gets its world seed and robot
     * @return the conditions
     * @throws ExperimentInputException naming the value if {@code robots} is below 1
     */
    public static RunConditions ofPopulation(String scenario, double timeScale, long seed, Double gridResolutionM,
                                             Long robotSeed, Integer robots, ExperimentDesign design) {
        if (robots != null && robots < 1) {
            throw new ExperimentInputException("--robots must be at least 1, got " + robots);
        }
        int size = robots != null ? robots : robotSeed != null ? 1 : POPULATION_ROBOTS;
        return new RunConditions(scenario, timeScale, seed, gridResolutionM,
                robotSeed != null ? robotSeed : POPULATION_FIRST_ROBOT_SEED, size, design);
    }

    /**
     * Validates the fields.
     *
     * @param scenario {@code paper-room} or the path of a scenario file, as given to {@code run}
     * @param timeScale world time runs this many times faster than wall time
     * @param seed the world seed of run 1 of set 1
     * @param gridResolutionM occupancy grid cell size in metres, or null for {@code run}'s default
     * @param robotSeed the first robot seed of the population
     * @param robots the population's size, at least 1
     * @param design how each run gets its world seed and its robot
     * @param cpuLimitCpus the CPU quota of each run, or null for none
     */
    public RunConditions {
        Objects.requireNonNull(scenario, "scenario");
        Objects.requireNonNull(design, "design");
        if (!(timeScale > 0) || Double.isInfinite(timeScale)) {
            throw new IllegalArgumentException("time scale must be positive, got " + timeScale);
        }
        if (gridResolutionM != null && !(gridResolutionM > 0)) {
            throw new IllegalArgumentException("grid resolution must be positive, got " + gridResolutionM);
        }
        if (robots < 1) {
            throw new IllegalArgumentException("robots must be at least 1, got " + robots);
        }
        if (cpuLimitCpus != null && CpuQuota.invalid(cpuLimitCpus) != null) {
            throw new IllegalArgumentException("--cpu-limit " + CpuQuota.invalid(cpuLimitCpus));
        }
    }

    /**
     * @param set a set number, from 1
     * @param run a run number, from 1
     * @return the world seed passed to that run ({@link ExperimentDesign#worldSeed})
     */
    public long seedOf(int set, int run) {
        return design.worldSeed(seed, set, run);
    }

    /**
     * @param set a set number, from 1
     * @param run a run number, from 1
     * @return the robot seed passed to that run: the same for every run with one robot
     */
    public long robotSeedOf(int set, int run) {
        return robotSeed + design.robotIndex(seedOf(set, run), run, robots);
    }

    /** @return how the runs get their seeds and robots, in words, for reports */
    public String robotsInWords() {
        String robotsText = robots == 1 ? "one robot (robot seed " + robotSeed + ") for every run"
                : "a population of " + robots + " robots (robot seeds " + robotSeed + ".." + (robotSeed + robots - 1) + ")";
        return switch (design) {
            case INDEPENDENT -> "independent runs: each its own world seed; " + robotsText
                    + (robots == 1 ? "" : ", each run drawing its robot from the population by its world seed");
            case BLOCKED -> "blocked: run j of every set shares world seed seed + j - 1"
                    + (robots == 1 ? "" : " and robot seed " + robotSeed + " + (j - 1) mod " + robots) + "; " + robotsText;
        };
    }
}
