package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * The position mediator's decision of one cycle: whose motion request went to the motors, or
 * why it stopped the robot. Mutable buffer for the data store; not thread-safe.
 */
public final class MediatorDecision implements StateValue<MediatorDecision> {

    /** The obstacle avoider's request went to the motors. */
    public static final int OBSTACLE = 0;
    /** The waypoint planner's request went to the motors. */
    public static final int WAYPOINT = 1;
    /** Stop: neither behavior requested control. */
    public static final int IDLE_STOP = 2;
    /** Stop: the avoider's request, or the winning waypoint request, was missing or too old. */
    public static final int STALE_STOP = 3;

    /** {@link #OBSTACLE}, {@link #WAYPOINT}, {@link #IDLE_STOP} or {@link #STALE_STOP}. */
    public int winner = IDLE_STOP;

    @Override
    public void copyFrom(MediatorDecision source) {
        winner = source.winner;
    }
}
