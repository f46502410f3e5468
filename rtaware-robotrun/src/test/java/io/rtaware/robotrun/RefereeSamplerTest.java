package io.rtaware.robotrun;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.monitor.SteppedThreads;
import io.rtaware.core.time.ManualClock;
import io.rtaware.robot.geometry.Pose2d;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.LongSupplier;
import org.junit.jupiter.api.Test;

/**
 * The referee's sampling thread on a manual clock: stepped from one due sample to the next, or
 * each step awaited through a latch (no timing).
 */
class RefereeSamplerTest {

    private static final long MS = 1_000_000L;

    /** A robot standing at (1, 2). */
    private static final Referee.PoseSource STANDING = new Referee.PoseSource() {
        @Override
        public Pose2d pose() {
            return new Pose2d(1, 2, 0);
        }

        @Override
        public String kind() {
            return "ground_truth";
        }
    };

    @Test
    void theSamplingThreadWaitsForEachSamplesWorldTimeAndSamplesThenExactlyOnce() {
        ManualClock clock = new ManualClock(0);
        Referee referee = new Referee(clock, 0, 100 * MS, STANDING, () -> 0).start();
        try {
            new SteppedThreads(referee.samplerIdle(), clock).runUntil(350 * MS);
            assertEquals(List.of(0.0, 0.1, 0.2, 0.3), referee.samples().stream().map(Referee.Sample::tS).toList(),
                    "one sample at the start and one at each 100 ms of world time, none between");
            assertEquals(300 * MS, clock.nanos(), "the clock was moved only to the samples' times");
        } finally {
            referee.close();
        }
    }

    @Test
    void aSampleThatThrowsIsCountedAndRecordedAsAGapAndSamplingGoesOnUntilClosed() throws Exception {
        ManualClock clock = new ManualClock(0);
        CountDownLatch[] reached = {new CountDownLatch(1), new CountDownLatch(1), new CountDownLatch(1)};
        AtomicInteger calls = new AtomicInteger();
        LongSupplier misses = () -> {
            int call = calls.incrementAndGet();
            if (call <= reached.length) {
                reached[call - 1].countDown();
            }
            if (call == 2) {
                throw new IllegalStateException("a fault of the miss counter");
            }
            return 0;
        };
        Referee referee = new Referee(clock, 0, 100 * MS, STANDING, misses).start();
        try {
            assertTrue(reached[0].await(10, TimeUnit.SECONDS), "the first sample, at the start");
            clock.advanceTo(100 * MS);
            assertTrue(reached[1].await(10, TimeUnit.SECONDS), "the second sample, 100 ms later, throws");
            clock.advanceTo(200 * MS);
            assertTrue(reached[2].await(10, TimeUnit.SECONDS), "the sampling went on after the error");
        } finally {
            referee.close();
        }

        assertEquals(1, referee.samplingErrors(), "the error was counted");
        assertTrue(referee.lastError().contains("a fault of the miss counter"), referee.lastError());
        assertEquals(List.of(new GroundTruthGap(0.0, 0.2, false)), referee.gaps(0.2),
                "the failed sample is a gap from the last pose before it to the first after it");
        assertEquals(List.of(0.0, 0.2, 0.2), referee.samples().stream().map(Referee.Sample::tS).toList(),
                "one sample at 0 s, one at 0.2 s by the sampling thread, the last by close; none while parked");
    }
}
