package io.rtaware.experiment;

import java.util.Arrays;
import java.util.Locale;

/**
 * How the runs of an experiment get their world seed (the noise of sensors, odometry and moving
 * people) and their robot (the systematic odometry errors of one simulated Koala, by robot seed),
 * and so which test fits the results.
 *
 * <ul>
 *   <li>{@link #INDEPENDENT} (the default): every run of every set has a world seed of its own and
 *   draws its robot from the population; the sets are independent samples, as Welch's t-test
 *   assumes.</li>
 *   <li>{@link #BLOCKED}: run j of every set shares world seed j and robot j, so each run number is
 *   a block; more powerful, but the sets are paired samples and the analysis must block on the run
 *   (paired differences, two-way ANOVA or Friedman), not compare the sets as independent. Every
 *   folder made before the design was recorded is blocked.</li>
 * </ul>
 *
 * Both are deterministic functions of the plan's seed, so a shard or a resumed experiment makes
 * exactly the runs of the whole plan.
 */
public enum ExperimentDesign {

    /** Every run its own world seed and a robot drawn from the population. */
    INDEPENDENT,
    /** Run j of every set shares world seed j and robot j. */
    BLOCKED;

    /**
     * Stride between the world seeds of two sets in the independent design: set i run j uses
     * {@code seed + (i - 1) * STRIDE + (j - 1)}, distinct for every run of a plan (runs per set are
     * at most {@link ExperimentPlan#MAX_RUNS_PER_SET}).
     */
    static final long SET_SEED_STRIDE = ExperimentPlan.MAX_RUNS_PER_SET;

    /** @return the name in plan.json, experiment.json, results.csv and on the command line */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * @param text {@code independent} or {@code blocked}
     * @return the design
     * @throws ExperimentInputException naming the value if it is neither
     */
    public static ExperimentDesign parse(String text) {
        for (ExperimentDesign d : values()) {
            if (d.label().equals(text)) {
                return d;
            }
        }
        throw new ExperimentInputException("the design must be one of " + Arrays.stream(values())
                .map(ExperimentDesign::label).toList() + ", got '" + text + "'");
    }

    /**
     * @param seed the plan's seed (run 1 of set 1)
     * @param set a set's number, from 1
     * @param run a run's number, from 1
     * @return the world seed of that run
     */
    public long worldSeed(long seed, int set, int run) {
        return this == BLOCKED ? seed + run - 1 : seed + (set - 1) * SET_SEED_STRIDE + run - 1;
    }

    /**
     * The inverse of {@link #worldSeed}: the plan's seed from one run's.
     *
     * @param worldSeed the run's world seed
     * @param set its set
     * @param run its run number
     * @return the plan's seed
     */
    public long planSeed(long worldSeed, int set, int run) {
        return worldSeed - worldSeed(0, set, run);
    }

    /**
     * Which robot of the population of {@code robots} a run drives, from 0: in the blocked design
     * robot {@code (run - 1) mod robots}, the same in every set; in the independent design a draw
     * from the run's world seed (SplitMix64's finalizer, then modulo: uniform to within
     * {@code robots / 2^64}), so every run draws its own robot, none chosen by how it drives.
     *
     * @param worldSeed the run's world seed ({@link #worldSeed})
     * @param run the run's number, from 1
     * @param robots the population's size, at least 1
     * @return the robot's index in the population, 0 to {@code robots - 1}
     */
    public int robotIndex(long worldSeed, int run, int robots) {
        if (this == BLOCKED) {
            return (run - 1) % robots;
        }
        return (int) Math.floorMod(mix64(worldSeed), (long) robots);
    }

    /** SplitMix64's output function: every input bit affects every output bit. */
    private static long mix64(long value) {
        long z = value + 0x9E3779B97F4A7C15L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
