package io.rtaware.robotrun;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.time.ManualClock;
import org.junit.jupiter.api.Test;

/** Every rule of the supervisor on a manual world clock and a manual wall clock: no sleeps. */
class SupervisorTest {

    private static final long S = 1_000_000_000L;

    /** A scripted view: the test sets what the run looks like. */
    private static final class Scripted implements Supervisor.View {
        boolean done;
        long generation;
        boolean stalled;
        boolean moving;
        double displacementM = Double.NaN;
        String fault;
        double trueDistanceM = Double.NaN;
        int refreshes;

        @Override
        public void refresh() {
            refreshes++;
        }

        @Override
        public boolean courseDone() {
            return done;
        }

        @Override
        public long odometryGeneration() {
            return generation;
        }

        @Override
        public boolean stalled() {
            return stalled;
        }

        @Override
        public boolean commandedToMove() {
            return moving;
        }

        @Override
        public double displacementOverLastM(double windowS) {
            assertEquals(30.0, windowS);
            return displacementM;
        }

        @Override
        public String safetyFault() {
            return fault;
        }

        @Override
        public double trueDistanceToFinishM() {
            return trueDistanceM;
        }
    }

    private final ManualClock world = new ManualClock(100 * S);
    private final long[] wallNs = {7 * S};
    private final Scripted view = new Scripted();
    private final Supervisor supervisor = new Supervisor(view, world, () -> wallNs[0], 100 * S, 360, 30);

    private void advance(long worldNs, long wallNanos) {
        world.advance(worldNs);
        wallNs[0] += wallNanos;
        view.generation++; // odometry keeps arriving unless a test says otherwise
    }

    @Test
    void aHealthyRunGoesOnUntilTheTimeLimit() {
        view.moving = true;
        view.displacementM = 1.0;
        advance(359 * S + 999_999_999L, S);
        assertNull(supervisor.check());
        advance(1, 0);
        RunState.Ending end = supervisor.check();
        assertEquals(RunOutcome.TIMEOUT, end.outcome());
        assertEquals("time limit of 360 s passed", end.reason());
        assertEquals(2, view.refreshes, "one read of the newest state per look");
    }

    @Test
    void theFinishWinsOverTheTimeLimit() {
        advance(400 * S, S);
        view.done = true;
        view.trueDistanceM = 1.0644;
        assertEquals(new RunState.Ending(RunOutcome.COMPLETED, "finish reached by odometry; 1.06 m from it in truth"),
                supervisor.check(), "the finish is the controller's belief; the truth is measured beside it");
    }

    @Test
    void theFinishsTruthIsShownFromTheMillimetreTheReportRecords() {
        advance(S, S);
        view.done = true;
        view.trueDistanceM = 0.28496; // recorded as 0.285 for the waypoint pass, which the report shows as 0.29
        assertEquals(new RunState.Ending(RunOutcome.COMPLETED, "finish reached by odometry; 0.29 m from it in truth"),
                supervisor.check(), "the ending and the pass's line agree on one pose");
    }

    @Test
    void withoutGroundTruthTheFinishClaimsOnlyOdometry() {
        advance(S, S);
        view.done = true;
        assertEquals(new RunState.Ending(RunOutcome.COMPLETED, "finish reached by odometry"), supervisor.check());
    }

    @Test
    void stuckOnlyWhileCommandedToMoveAndOnlyOnceTheWindowIsFull() {
        advance(10 * S, S);
        view.moving = true;
        assertNull(supervisor.check(), "the run is younger than the window: NaN displacement");
        view.displacementM = 0.0499;
        view.moving = false;
        assertNull(supervisor.check(), "a robot told to stop is not stuck");
        view.moving = true;
        RunState.Ending end = supervisor.check();
        assertEquals(RunOutcome.STUCK, end.outcome());
        assertEquals("moved less than 0.05 m in 30 s while commanded to move", end.reason());
        view.displacementM = 0.05;
        assertNull(supervisor.check(), "0.05 m is moving");
    }

    @Test
    void aLostServerNeedsBothWorldAndWallTimeWithoutOdometry() {
        advance(S, S); // one odometry commit
        assertNull(supervisor.check());
        long generation = view.generation;
        world.advance(5 * S + 1);
        wallNs[0] += 3 * S; // a loaded machine: 5 s of world time but only 3 s of wall time
        view.generation = generation;
        assertNull(supervisor.check(), "not lost until 3 s of wall time passed too");
        wallNs[0] += 1;
        RunState.Ending end = supervisor.check();
        assertEquals(RunOutcome.ERROR, end.outcome());
        assertTrue(end.reason().startsWith("no odometry from the robot server for 5 s of world time"), end.reason());
        view.generation++;
        assertNull(supervisor.check(), "a new commit resets the silence");
    }

    @Test
    void aSafetyFaultEndsTheRunAsAnErrorAtOnceWithTheFaultAsReason() {
        advance(S, S);
        view.done = true; // even beside a finish, impossible data is the ending
        view.fault = "position2d:0 sent only impossible samples for 1.0 s of world time: x = NaN; robot halted";
        RunState.Ending end = supervisor.check();
        assertEquals(RunOutcome.ERROR, end.outcome());
        assertEquals(view.fault, end.reason());
        assertEquals(1, end.outcome().exitStatus());
    }

    @Test
    void countsRisingEdgesOfTheStallFlag() {
        for (boolean stall : new boolean[] {false, true, true, false, true, false, false, true}) {
            view.stalled = stall;
            advance(S / 10, S / 10);
            supervisor.check();
        }
        assertEquals(3, supervisor.stallEdges());
    }

    @Test
    void outcomesKeepTheirReportNamesAndExitStatuses() {
        assertEquals("completed timeout stuck interrupted error", String.join(" ",
                java.util.Arrays.stream(RunOutcome.values()).map(RunOutcome::jsonName).toList()));
        assertEquals(0, RunOutcome.COMPLETED.exitStatus());
        assertEquals(0, RunOutcome.STUCK.exitStatus());
        assertEquals(130, RunOutcome.INTERRUPTED.exitStatus());
    }

    @Test
    void runStateKeepsTheFirstEndingAndAStartBeforeTheMonitorStarts() {
        RunState state = new RunState(42);
        assertEquals(42, state.startNs(), "Ctrl-C before the start measures from the state's creation");
        assertNull(state.referee());
        assertEquals(0, state.stallEdges());
        assertEquals(100 - 42, state.elapsedNs(100), "while the run goes on: to now");
        assertTrue(state.end(RunOutcome.STUCK, "stuck", 142));
        assertTrue(!state.end(RunOutcome.INTERRUPTED, "interrupted", 900));
        assertEquals(RunOutcome.STUCK, state.outcome());
        assertEquals(100, state.elapsedNs(1_000), "the run's time ends at its ending, not when the report is written");
    }
}
