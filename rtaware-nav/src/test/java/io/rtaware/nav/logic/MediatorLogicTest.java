package io.rtaware.nav.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.nav.logic.MediatorLogic.Decision;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.VelocityCommand;
import org.junit.jupiter.api.Test;

class MediatorLogicTest {

    private final MotionRequest avoid = new MotionRequest();
    private final MotionRequest waypoint = new MotionRequest();
    private final VelocityCommand motor = new VelocityCommand();

    @Test
    void avoiderWinsWhenItAsksForControl() {
        avoid.request(0.03, -0.5);
        waypoint.request(0.1, 0.2);
        assertEquals(Decision.OBSTACLE, MediatorLogic.decide(true, avoid, true, waypoint, motor));
        assertEquals(0.03, motor.vxMps);
        assertEquals(-0.5, motor.omegaRadPerSec);
    }

    @Test
    void waypointPlannerDrivesOtherwise() {
        avoid.release();
        waypoint.request(0.1, 0.2);
        assertEquals(Decision.WAYPOINT, MediatorLogic.decide(true, avoid, true, waypoint, motor));
        assertEquals(0.1, motor.vxMps);
        assertEquals(0.2, motor.omegaRadPerSec);
    }

    @Test
    void nobodyAskingStops() {
        avoid.release();
        waypoint.release();
        motor.set(1, 1);
        assertEquals(Decision.IDLE_STOP, MediatorLogic.decide(true, avoid, true, waypoint, motor));
        assertTrue(motor.isStop());
    }

    @Test
    void staleOrMissingAvoiderStopsWhateverItLastSaid() {
        avoid.release();
        waypoint.request(0.1, 0);
        motor.set(1, 1);
        assertEquals(Decision.STALE_STOP, MediatorLogic.decide(false, avoid, true, waypoint, motor));
        assertTrue(motor.isStop());
        avoid.request(0.03, 0.5);
        assertEquals(Decision.STALE_STOP, MediatorLogic.decide(false, avoid, true, waypoint, motor));
        assertTrue(motor.isStop());
    }

    @Test
    void staleWinningWaypointRequestStopsButAFreshAvoiderStillWins() {
        avoid.release();
        waypoint.request(0.1, 0);
        assertEquals(Decision.STALE_STOP, MediatorLogic.decide(true, avoid, false, waypoint, motor));
        assertTrue(motor.isStop());
        avoid.request(0.03, 0.5);
        assertEquals(Decision.OBSTACLE, MediatorLogic.decide(true, avoid, false, waypoint, motor),
                "the stale request did not win");
    }
}
