package io.rtaware.nav.logic;

import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.VelocityCommand;

/**
 * The position mediator's decision: the obstacle avoider wins when it requests control,
 * otherwise the waypoint planner; nothing requested means stop. Staleness is a safety rule: if
 * the avoider's request is missing or older than its declared maximum age, the robot stops,
 * whatever that request said (a late safety task must never leave the robot driving blind);
 * if the waypoint planner would win but its request is missing or too old, the robot stops too.
 *
 * <p>Stateless, hence thread-safe; allocates nothing.
 */
public final class MediatorLogic {

    /** Who decided a cycle's motor command. */
    public enum Decision {
        /** The obstacle avoider's request went to the motors. */
        OBSTACLE,
        /** The waypoint planner's request went to the motors. */
        WAYPOINT,
        /** Stop: neither behavior requested control. */
        IDLE_STOP,
        /** Stop: the avoider's request, or the winning waypoint request, was missing or too old. */
        STALE_STOP
    }

    private MediatorLogic() {
    }

    /**
     * Decides one cycle.
     *
     * @param avoidFresh true if the avoider's request exists and is within its maximum age
     * @param avoid the avoider's request
     * @param waypointFresh true if the waypoint planner's request exists and is within its
     *     maximum age
     * @param waypoint the waypoint planner's request
     * @param out receives the motor command
     * @return who decided
     */
    public static Decision decide(boolean avoidFresh, MotionRequest avoid, boolean waypointFresh, MotionRequest waypoint,
                           VelocityCommand out) {
        if (!avoidFresh) {
            out.set(0, 0);
            return Decision.STALE_STOP;
        }
        if (avoid.active) {
            out.set(avoid.vxMps, avoid.omegaRadPerSec);
            return Decision.OBSTACLE;
        }
        if (!waypointFresh) {
            out.set(0, 0);
            return Decision.STALE_STOP;
        }
        if (waypoint.active) {
            out.set(waypoint.vxMps, waypoint.omegaRadPerSec);
            return Decision.WAYPOINT;
        }
        out.set(0, 0);
        return Decision.IDLE_STOP;
    }
}
