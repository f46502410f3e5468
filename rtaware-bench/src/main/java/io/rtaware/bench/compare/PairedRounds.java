package io.rtaware.bench.compare;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.SplittableRandom;
import org.apache.commons.math3.stat.descriptive.rank.Median;
import org.apache.commons.math3.stat.inference.WilcoxonSignedRankTest;

/**
 * Whether one executor does worse than another beyond the machine's noise, judged round by round.
 * Round r runs one segment of every executor back to back, so the two executors' segments of a
 * round saw nearly the same machine: a pair. Near overload the misses come in clusters (one
 * stall of a few hundred milliseconds costs thousands of releases), so the ratio of two totals
 * swings between runs; the pairs say how far:
 * <ul>
 *   <li>a 95 % confidence interval of the ratio of the two executors' miss totals, by a paired
 *   bootstrap over rounds ({@value #BOOTSTRAP_RESAMPLES} resamples of the rounds with
 *   replacement, the same rounds for both executors, percentile interval, fixed seed so a
 *   report reads the same when printed twice);</li>
 *   <li>in how many rounds each did worse, and the two-sided p-value of Wilcoxon's signed-rank
 *   test on the per-round miss shares (commons-math; exact for up to 30 rounds; rounds where
 *   both are equal are left out, as Wilcoxon's test does);</li>
 *   <li>the same for each round's p99.9 lateness, with the median of the per-round ratios.</li>
 * </ul>
 */
public final class PairedRounds {

    /** Bootstrap resamples behind each interval. */
    static final int BOOTSTRAP_RESAMPLES = 2000;
    /** The bootstrap's seed: the same rounds always give the same interval. */
    private static final long SEED = 16;
    /** Largest number of non-tied rounds for which commons-math computes the exact p-value. */
    private static final int EXACT_P_MAX_ROUNDS = 30;
    /** The executor pairs a comparison reports: each of rtaware's executors with the one it must beat. */
    private static final List<List<String>> PAIRS =
            List.of(List.of("rtaware", "park-loop"), List.of("rtaware-pooled", "stpe-pooled"));

    private PairedRounds() {
    }

    /**
     * One executor against a baseline over the rounds both ran.
     *
     * @param executor the executor judged
     * @param baseline the one it is compared with
     * @param rounds rounds compared
     * @param missesRatio the executor's misses over the baseline's, all rounds (infinite if only
     *        the baseline had none; 1 if neither had any)
     * @param missesRatioCi95Low lower end of the ratio's 95 % bootstrap interval
     * @param missesRatioCi95High upper end of it
     * @param roundsMoreMisses rounds in which the executor missed a larger share of its releases
     * @param roundsFewerMisses rounds in which it missed a smaller share
     * @param missesP two-sided Wilcoxon signed-rank p-value of the per-round miss shares (1 if
     *        every round was a tie)
     * @param p999MedianRoundRatio median over rounds of the executor's p99.9 lateness over the baseline's
     * @param roundsHigherP999 rounds in which the executor's p99.9 was higher
     * @param roundsLowerP999 rounds in which it was lower
     * @param p999P two-sided Wilcoxon signed-rank p-value of the per-round p99.9 values
     */
    public record Paired(String executor, String baseline, int rounds, double missesRatio,
                         double missesRatioCi95Low, double missesRatioCi95High, int roundsMoreMisses,
                         int roundsFewerMisses, double missesP, double p999MedianRoundRatio, int roundsHigherP999,
                         int roundsLowerP999, double p999P) {

        /** @return one line for a person */
        public String line() {
            return String.format(Locale.ROOT, "%s vs %s over %d rounds: misses x%s (95 %% CI %s-%s), more in %d"
                            + " rounds, fewer in %d, Wilcoxon p = %.3f; p99.9 x%.2f (median round), higher in %d,"
                            + " lower in %d, p = %.3f",
                    executor, baseline, rounds, ratio(missesRatio), ratio(missesRatioCi95Low),
                    ratio(missesRatioCi95High), roundsMoreMisses, roundsFewerMisses, missesP, p999MedianRoundRatio,
                    roundsHigherP999, roundsLowerP999, p999P);
        }

        /** @return the interval for a goal's line, e.g. {@code 95 % CI 1.10-3.20 over 12 rounds} */
        String interval() {
            return String.format(Locale.ROOT, "95 %% CI %s-%s over %d rounds", ratio(missesRatioCi95Low),
                    ratio(missesRatioCi95High), rounds);
        }

        private static String ratio(double r) {
            return Double.isInfinite(r) ? "inf" : String.format(Locale.ROOT, "%.2f", r);
        }
    }

    /**
     * @param runs a comparison's rows
     * @return the standard pairs present among them with rounds to compare (rtaware against the
     *     park loop, rtaware's pool against the pooled STPE)
     */
    public static List<Paired> check(List<RunResult> runs) {
        List<Paired> out = new ArrayList<>();
        for (List<String> pair : PAIRS) {
            Optional<RunResult> subject = find(runs, pair.get(0));
            Optional<RunResult> baseline = find(runs, pair.get(1));
            if (subject.isPresent() && baseline.isPresent()) {
                compare(subject.get(), baseline.get()).ifPresent(out::add);
            }
        }
        return out;
    }

    /**
     * @param subject the executor judged
     * @param baseline the one it is compared with
     * @return the comparison, or empty unless both have the same number of rounds, at least two
     */
    public static Optional<Paired> compare(RunResult subject, RunResult baseline) {
        List<RunResult.Round> a = subject.rounds();
        List<RunResult.Round> b = baseline.rounds();
        int n = a.size();
        if (n < 2 || b.size() != n) {
            return Optional.empty();
        }
        long[] missesA = new long[n];
        long[] missesB = new long[n];
        double[] shareA = new double[n];
        double[] shareB = new double[n];
        double[] p999A = new double[n];
        double[] p999B = new double[n];
        for (int r = 0; r < n; r++) {
            missesA[r] = a.get(r).misses();
            missesB[r] = b.get(r).misses();
            shareA[r] = share(a.get(r));
            shareB[r] = share(b.get(r));
            p999A[r] = a.get(r).p999Us();
            p999B[r] = b.get(r).p999Us();
        }
        double[] interval = bootstrapRatioInterval(missesA, missesB);
        return Optional.of(new Paired(subject.executor(), baseline.executor(), n,
                ratio(Arrays.stream(missesA).sum(), Arrays.stream(missesB).sum()), interval[0], interval[1],
                count(shareA, shareB), count(shareB, shareA), wilcoxonP(shareA, shareB),
                medianRatio(p999A, p999B), count(p999A, p999B), count(p999B, p999A), wilcoxonP(p999A, p999B)));
    }

    private static double share(RunResult.Round round) {
        return round.releases() == 0 ? 0 : (double) round.misses() / round.releases();
    }

    /** @return the ratio of two totals: infinite if only the denominator is 0, 1 if both are */
    static double ratio(double numerator, double denominator) {
        if (denominator == 0) {
            return numerator == 0 ? 1.0 : Double.POSITIVE_INFINITY;
        }
        return numerator / denominator;
    }

    /** 2.5th and 97.5th percentiles (nearest rank) of the ratio of totals over resampled rounds. */
    private static double[] bootstrapRatioInterval(long[] a, long[] b) {
        int n = a.length;
        SplittableRandom random = new SplittableRandom(SEED);
        double[] ratios = new double[BOOTSTRAP_RESAMPLES];
        for (int i = 0; i < BOOTSTRAP_RESAMPLES; i++) {
            long sumA = 0;
            long sumB = 0;
            for (int j = 0; j < n; j++) {
                int r = random.nextInt(n);
                sumA += a[r];
                sumB += b[r];
            }
            ratios[i] = ratio(sumA, sumB);
        }
        Arrays.sort(ratios);
        return new double[] {nearestRank(ratios, 2.5), nearestRank(ratios, 97.5)};
    }

    private static double nearestRank(double[] sorted, double percent) {
        int rank = (int) Math.ceil(percent / 100.0 * sorted.length);
        return sorted[Math.max(0, rank - 1)];
    }

    /** @return rounds in which {@code x} is greater than {@code y} */
    private static int count(double[] x, double[] y) {
        int c = 0;
        for (int i = 0; i < x.length; i++) {
            if (x[i] > y[i]) {
                c++;
            }
        }
        return c;
    }

    /** Two-sided Wilcoxon signed-rank p-value over the pairs that differ, at most 1; 1 if none does. */
    static double wilcoxonP(double[] x, double[] y) {
        int differing = count(x, y) + count(y, x);
        if (differing == 0) {
            return 1.0;
        }
        double[] dx = new double[differing];
        double[] dy = new double[differing];
        int k = 0;
        for (int i = 0; i < x.length; i++) {
            if (x[i] != y[i]) {
                dx[k] = x[i];
                dy[k] = y[i];
                k++;
            }
        }
        // the exact test doubles P(W >= W max); with tied ranks W max can sit below the middle of
        // the distribution and the doubled tail exceeds 1 (ranks 1.5, 1.5, 3 with W+ = W- = 3: 2 * 5/8)
        return Math.min(1.0, new WilcoxonSignedRankTest().wilcoxonSignedRankTest(dx, dy,
                differing <= EXACT_P_MAX_ROUNDS));
    }

    private static double medianRatio(double[] a, double[] b) {
        double[] ratios = new double[a.length];
        for (int i = 0; i < a.length; i++) {
            ratios[i] = ratio(a[i], b[i]);
        }
        return new Median().evaluate(ratios);
    }

    private static Optional<RunResult> find(List<RunResult> runs, String executor) {
        return runs.stream().filter(r -> r.executor().equals(executor)).findFirst();
    }
}
