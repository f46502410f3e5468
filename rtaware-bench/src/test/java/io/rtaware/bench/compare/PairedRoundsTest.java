package io.rtaware.bench.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The round-by-round judgement of two executors, on rounds made by hand. */
class PairedRoundsTest {

    private static RunResult run(String executor, long[] misses, double[] p999Us) {
        List<RunResult.Round> rounds = new ArrayList<>();
        long total = 0;
        for (int r = 0; r < misses.length; r++) {
            rounds.add(new RunResult.Round(1000, misses[r], p999Us[r]));
            total += misses[r];
        }
        return new RunResult(executor, new RunResult.Lateness(1, 2, 3, 4), 1000L * misses.length, total, 0, 1, 0,
                rounds);
    }

    private static double[] same(int n, double v) {
        double[] a = new double[n];
        java.util.Arrays.fill(a, v);
        return a;
    }

    @Test
    void anExecutorWorseInEveryRoundIsWorseBeyondDoubt() {
        RunResult subject = run("rtaware", new long[] {2, 4, 6, 8, 10, 12, 14, 16, 18, 20}, same(10, 300));
        RunResult floor = run("park-loop", new long[] {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, same(10, 100));
        PairedRounds.Paired p = PairedRounds.compare(subject, floor).orElseThrow();
        assertEquals(10, p.rounds());
        assertEquals(2.0, p.missesRatio());
        assertEquals(2.0, p.missesRatioCi95Low(), "every resample keeps the ratio of 2");
        assertEquals(2.0, p.missesRatioCi95High());
        assertEquals(10, p.roundsMoreMisses());
        assertEquals(0, p.roundsFewerMisses());
        assertEquals(2.0 / 1024, p.missesP(), 1e-12, "exact two-sided: only 1 of 2^10 sign patterns is as extreme, twice");
        assertEquals(3.0, p.p999MedianRoundRatio());
        assertEquals(10, p.roundsHigherP999());
        assertEquals(2.0 / 1024, p.p999P(), 1e-12);
    }

    @Test
    void tiedDifferencesNeverGiveAPAboveOne() {
        // differences +1, +1, -2 per mille: the two ties share rank 1.5, W+ = W- = 3; the exact test
        // counted 5 of 8 sign patterns at or above 3 and doubled it: 'Wilcoxon p = 1.250' in bench --compare
        RunResult subject = run("rtaware", new long[] {2, 2, 1}, new double[] {101, 101, 100});
        RunResult floor = run("park-loop", new long[] {1, 1, 3}, new double[] {100, 100, 102});
        PairedRounds.Paired p = PairedRounds.compare(subject, floor).orElseThrow();
        assertEquals(1.0, p.missesP(), "a two-sided p-value is a probability: at most 1");
        assertEquals(1.0, p.p999P(), "the same for p99.9");
        assertTrue(p.line().contains("Wilcoxon p = 1.000"), p.line());
    }

    @Test
    void equalRoundsShowNoDifference() {
        long[] misses = {3, 0, 7, 1, 0, 2};
        PairedRounds.Paired p = PairedRounds.compare(run("rtaware", misses, same(6, 50)),
                run("park-loop", misses, same(6, 50))).orElseThrow();
        assertEquals(1.0, p.missesRatio());
        assertEquals(1.0, p.missesRatioCi95Low());
        assertEquals(1.0, p.missesRatioCi95High());
        assertEquals(0, p.roundsMoreMisses() + p.roundsFewerMisses());
        assertEquals(1.0, p.missesP(), "ties are left out; with none left there is no evidence either way");
        assertEquals(1.0, p.p999P());
    }

    @Test
    void oneStallInOneRoundWidensTheIntervalAndIsNotSignificant() {
        // Eleven quiet rounds alike, then one stall of the subject's: the total ratio is large, but
        // it rests on one round, and the interval and the test say so.
        long[] subject = {5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 1000};
        long[] floor = {5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5};
        PairedRounds.Paired p = PairedRounds.compare(run("rtaware", subject, same(12, 10)),
                run("park-loop", floor, same(12, 10))).orElseThrow();
        assertEquals(1055.0 / 60, p.missesRatio(), 1e-9);
        assertEquals(1.0, p.missesRatioCi95Low(), "resamples without the stall round give 1");
        assertTrue(p.missesRatioCi95High() > 25, "resamples with it twice or more: " + p.missesRatioCi95High());
        assertEquals(1, p.roundsMoreMisses());
        assertEquals(1.0, p.missesP(), 1e-12, "one differing round: both signs equally likely");
        PairedRounds.Paired again = PairedRounds.compare(run("rtaware", subject, same(12, 10)),
                run("park-loop", floor, same(12, 10))).orElseThrow();
        assertEquals(p, again, "a fixed seed: the same rounds give the same interval");
    }

    @Test
    void aBaselineWithoutMissesMakesTheRatioInfinite() {
        PairedRounds.Paired p = PairedRounds.compare(run("rtaware", new long[] {1, 0, 2}, same(3, 10)),
                run("park-loop", new long[] {0, 0, 0}, same(3, 10))).orElseThrow();
        assertEquals(Double.POSITIVE_INFINITY, p.missesRatio());
        assertEquals(Double.POSITIVE_INFINITY, p.missesRatioCi95High());
        assertTrue(p.line().contains("misses xinf"), p.line());
    }

    @Test
    void nothingToPairWithoutMatchingRounds() {
        RunResult two = run("rtaware", new long[] {1, 2}, same(2, 10));
        RunResult three = run("park-loop", new long[] {1, 2, 3}, same(3, 10));
        assertTrue(PairedRounds.compare(two, three).isEmpty(), "rounds differ in number");
        RunResult one = run("rtaware", new long[] {1}, same(1, 10));
        assertTrue(PairedRounds.compare(one, run("park-loop", new long[] {1}, same(1, 10))).isEmpty(), "one round");
        assertTrue(PairedRounds.compare(new RunResult("rtaware", new RunResult.Lateness(1, 2, 3, 4), 1, 0, 0, 1, 0),
                new RunResult("park-loop", new RunResult.Lateness(1, 2, 3, 4), 1, 0, 0, 1, 0)).isEmpty(), "no rounds");
    }

    @Test
    void checkPairsEachOfRtawaresExecutorsWithItsBaseline() {
        long[] m = {1, 2, 3};
        List<PairedRounds.Paired> all = PairedRounds.check(List.of(run("rtaware", m, same(3, 1)),
                run("rtaware-pooled", m, same(3, 1)), run("stpe", m, same(3, 1)), run("stpe-pooled", m, same(3, 1)),
                run("park-loop", m, same(3, 1))));
        assertEquals(List.of("rtaware vs park-loop", "rtaware-pooled vs stpe-pooled"),
                all.stream().map(p -> p.executor() + " vs " + p.baseline()).toList());
    }
}
