package io.rtaware.robot.validate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.Odometry;
import org.junit.jupiter.api.Test;

/**
 * The timestamp rule of {@link SampleValidator} on stepped source time: a sample never earlier
 * than the previous one, a jump forward beyond a bound rejected, and a sustained restart of the
 * source's clock followed as a new epoch (issue 24, finding 6).
 */
class SampleValidatorEpochTest {

    /** Source time between two genuine samples: a 20 Hz odometry. */
    private static final double STEP_S = 0.05;

    private final SampleValidator odom = new SampleValidator("odom", SampleLimits.defaults());
    private final Odometry o = new Odometry();

    private boolean accept(double timeS) {
        o.serverTimeS = timeS;
        return odom.acceptOdometry(o);
    }

    @Test
    void oneSampleStampedFarAheadIsRejectedAndTheGenuineStreamGoesOn() {
        for (int i = 0; i <= 10; i++) {
            assertTrue(accept(100 + i * STEP_S), "genuine sample " + i);
        }
        assertFalse(accept(1100.5), "a sample stamped 1000 s ahead");
        assertTrue(odom.lastRejection().contains("1100.5"), odom.lastRejection());
        for (int i = 11; i <= 40; i++) {
            assertTrue(accept(100 + i * STEP_S), "genuine sample " + i + " after the one far ahead");
        }
        assertEquals(1, odom.rejected());
        assertEquals(41, odom.accepted());
        assertEquals(0, odom.clockEpochs(), "one sample far ahead is not a new clock");
    }

    @Test
    void aJumpForwardWithinTheBoundIsAccepted() {
        assertTrue(accept(100));
        assertTrue(accept(100 + SampleValidator.MAX_FORWARD_JUMP_S), "exactly the bound");
        assertFalse(accept(100 + 2 * SampleValidator.MAX_FORWARD_JUMP_S + 0.001), "just beyond it");
        assertEquals(1, odom.rejected());
    }

    @Test
    void aRestartedSourceClockIsFollowedAsANewEpochAfterItsSamplesAgree() {
        for (int i = 0; i <= 100; i++) {
            assertTrue(accept(500 + i * STEP_S));
        }
        // the simulator restarts with simulated time from 0: every genuine sample is now earlier
        int n = SampleValidator.EPOCH_AFTER_SAMPLES;
        for (int i = 0; i < n - 1; i++) {
            assertFalse(accept(i * STEP_S), "sample " + i + " of the new clock, not yet confirmed");
            assertTrue(odom.lastRejection().contains("earlier than the previous"), odom.lastRejection());
        }
        assertTrue(accept((n - 1) * STEP_S), "the " + n + "th agreeing sample starts the new epoch");
        for (int i = n; i < n + 50; i++) {
            assertTrue(accept(i * STEP_S), "followed: sample " + i + " of the new epoch");
        }
        assertEquals(n - 1, odom.rejected());
        assertEquals(1, odom.clockEpochs());
        assertEquals("odom: clock epoch 2 from 0.0 s (the previous sample was at 505.0 s; 3 samples in a row agreed)",
                odom.lastClockEpoch());
    }

    @Test
    void aSourceThatStartedFarAheadIsFollowedBackToItsGenuineClock() {
        assertTrue(accept(1000), "the first sample of a connection has no previous one");
        for (int i = 0; i < SampleValidator.EPOCH_AFTER_SAMPLES - 1; i++) {
            assertFalse(accept(1 + i * STEP_S));
        }
        assertTrue(accept(1 + (SampleValidator.EPOCH_AFTER_SAMPLES - 1) * STEP_S));
        assertEquals(1, odom.clockEpochs());
        odom.restart();
        assertTrue(accept(2000), "a new connection starts without a previous sample");
        assertEquals(1, odom.clockEpochs(), "a reconnection is not counted as an epoch");
    }

    @Test
    void samplesThatDoNotAgreeWithEachOtherNeverMakeAnEpoch() {
        assertTrue(accept(500));
        // stale samples in no order, each of them earlier than 500 s, several seconds apart
        double[] stale = {3, 1, 40, 2, 80, 0.5, 300, 7, 200, 9};
        for (double t : stale) {
            assertFalse(accept(t), "stale sample at " + t + " s");
        }
        assertFalse(accept(499.9), "still the old epoch's rule");
        assertTrue(accept(500.05));
        assertEquals(0, odom.clockEpochs());
        assertEquals(null, odom.lastClockEpoch());
    }

    @Test
    void aLongRunOfOneSampleFarAheadPerSecondNeverTakesOver() {
        // a hostile peer interleaving far-ahead samples with the genuine stream
        for (int i = 0; i < 200; i++) {
            assertTrue(accept(10 + i * STEP_S), "genuine " + i);
            if (i % 20 == 0) {
                assertFalse(accept(5000 + i), "far ahead at genuine sample " + i);
            }
        }
        assertEquals(10, odom.rejected());
        assertEquals(0, odom.clockEpochs());
    }
}
