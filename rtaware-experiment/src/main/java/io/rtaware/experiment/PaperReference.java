package io.rtaware.experiment;

import java.util.List;

/**
 * The numbers the paper published (Tables I and II, and the t-test results quoted in Section
 * VII), shown beside ours in the report and always labelled as the paper's. The paper's runs
 * were on a K-Team Koala robot with an Intel Core Duo 1.66 GHz, ten runs per set.
 */
public final class PaperReference {

    /** Runs per set in the paper. */
    public static final int RUNS_PER_SET = 10;

    /** The paper's robot's top speed, m/s (Section VII). */
    public static final double TOP_SPEED_MPS = 0.1;

    /**
     * One row of the paper's Tables I and II.
     *
     * @param periods the set as in Table I
     * @param runTimeMeanS average run time, s (Table I)
     * @param runTimeSdS its standard deviation, s (Table I)
     * @param distanceMeanM average distance to the finish, m (Table II)
     * @param distanceSdM its standard deviation, m (Table II)
     * @param distanceMinM smallest distance, m (Table II)
     * @param distanceMaxM largest distance, m (Table II)
     */
    public record PaperSet(PeriodSet periods, double runTimeMeanS, double runTimeSdS, double distanceMeanM,
                           double distanceSdM, double distanceMinM, double distanceMaxM) {
    }

    /**
     * A t-test result the paper states in words.
     *
     * @param setA first set's number, or null for a statement about every pair
     * @param setB second set's number, or null for a statement about every pair
     * @param quantity {@code run_time_s} or {@code distance_to_finish_m}
     * @param statement what the paper says
     */
    public record PaperTest(Integer setA, Integer setB, String quantity, String statement) {
    }

    /**
     * @param sets Tables I and II
     * @param tests the t-test results quoted in Section VII
     * @param source where the numbers come from
     */
    public record Published(List<PaperSet> sets, List<PaperTest> tests, String source) {
    }

    private PaperReference() {
    }

    /** @return the paper's published numbers */
    public static Published published() {
        List<PeriodSet> p = ExperimentSets.paper();
        return new Published(List.of(
                new PaperSet(p.get(0), 266.95, 6.64, 2.19, 0.17, 2.04, 2.45),
                new PaperSet(p.get(1), 267.34, 10.39, 2.21, 0.23, 2.02, 2.59),
                new PaperSet(p.get(2), 265.89, 11.19, 2.18, 0.21, 1.96, 2.45),
                new PaperSet(p.get(3), 276.97, 5.17, 2.14, 0.43, 1.80, 2.86),
                new PaperSet(p.get(4), 272.68, 6.28, 1.93, 0.17, 1.70, 2.12)),
                List.of(
                        new PaperTest(1, 4, "run_time_s", "statistically different"),
                        new PaperTest(1, 5, "run_time_s", "statistically different"),
                        new PaperTest(2, 4, "run_time_s", "confidence 82%"),
                        new PaperTest(3, 4, "run_time_s", "confidence 85%"),
                        new PaperTest(4, 5, "run_time_s", "confidence 79%"),
                        new PaperTest(null, null, "distance_to_finish_m", "no pair of sets statistically different")),
                "Tables I and II and Section VII of the paper (K-Team Koala robot, Intel Core Duo 1.66 GHz, 10 runs per set)");
    }

    /**
     * @param periods a set's periods
     * @return the paper's row with the same periods and the paper's top speed (a set without a
     *     top speed runs at {@code run}'s default, the paper's), or null if the paper has none
     */
    public static PaperSet matching(PeriodSet periods) {
        if (periods.topSpeedMps() != null && periods.topSpeedMps() != TOP_SPEED_MPS) {
            return null;
        }
        return published().sets().stream().filter(s -> s.periods().periodsMs().equals(periods.periodsMs()))
                .findFirst().orElse(null);
    }
}
