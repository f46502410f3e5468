package io.rtaware.robotrun;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import io.rtaware.core.time.ManualClock;
import io.rtaware.robot.geometry.Pose2d;
import java.io.IOException;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The referee's measurement across a lost ground truth, sampled by hand on a manual clock. */
class RefereeGapsTest {

    private static final long MS = 1_000_000L;

    /** Answers from a script: a pose, null (no pose) or an I/O failure. */
    private static final class Scripted implements Referee.PoseSource {
        final Deque<Object> answers = new ArrayDeque<>();

        @Override
        public Pose2d pose() throws IOException {
            Object next = answers.removeFirst();
            if (next instanceof IOException e) {
                throw e;
            }
            return next == NONE ? null : (Pose2d) next;
        }

        @Override
        public String kind() {
            return "ground_truth";
        }
    }

    private static final Object NONE = new Object();

    private final ManualClock clock = new ManualClock(5_000 * MS);
    private final Scripted source = new Scripted();
    private final Referee referee = new Referee(clock, 5_000 * MS, 100 * MS, source, () -> 0);

    private void sampleAt(long tMs, Object answer) {
        clock.advanceTo(5_000 * MS + tMs * MS);
        source.answers.add(answer);
        referee.sample();
    }

    @Test
    void aLostConnectionIsAGapAndTheDistanceAcrossItIsNotMeasured() {
        sampleAt(0, new Pose2d(0, 0, 0));
        sampleAt(100, new Pose2d(1, 0, 0));
        sampleAt(200, new IOException("connection lost")); // the simulator is killed
        sampleAt(700, new IOException("connection refused"));
        sampleAt(1200, NONE);
        sampleAt(2300, new Pose2d(0, 0, 0)); // restarted: the robot is back at the start
        sampleAt(2400, new Pose2d(0, 0.5, 0));
        assertEquals(List.of(new GroundTruthGap(0.1, 2.3, false)), referee.gaps(2.5));
        assertEquals(1.5, referee.travelledM(), 1e-12, "1 m before the gap, 0.5 m after; the jump is not driven");
        assertEquals("connection refused", referee.lastError());
    }

    @Test
    void aGapStillOpenAtTheEndLeavesTheFinalPoseStale() {
        sampleAt(0, new Pose2d(0, 0, 0));
        sampleAt(100, new Pose2d(0.1, 0, 0));
        sampleAt(200, new IOException("connection lost"));
        assertEquals(List.of(new GroundTruthGap(0.1, 3.0, true)), referee.gaps(3.0));
        assertEquals(0.1, referee.travelledM(), 1e-12);
    }

    @Test
    void samplesThatMerelyComeLateAreNoGapAndAnUnmeasuredRunIsOneOpenGap() {
        assertEquals(List.of(new GroundTruthGap(0, 1.0, true)), referee.gaps(1.0), "no pose at all");
        assertNull(referee.latest());
        sampleAt(0, new Pose2d(0, 0, 0));
        sampleAt(3000, new Pose2d(3, 4, 0)); // a stalled sampling thread, not a failure
        assertEquals(List.of(), referee.gaps(3.0));
        assertEquals(5.0, referee.travelledM(), 1e-12);
    }
}
