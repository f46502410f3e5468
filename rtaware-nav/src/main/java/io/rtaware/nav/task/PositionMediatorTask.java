package io.rtaware.nav.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.nav.logic.MediatorLogic;
import io.rtaware.robot.msg.MediatorDecision;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import java.time.Duration;

/**
 * The position mediator ({@code mediator}): consumes {@code motion.avoid} and
 * {@code motion.waypoint}, each with a declared maximum age, and publishes on {@code motor}
 * every cycle the command {@link MediatorLogic} decides, and on {@code mediator.decision} who won
 * (so a recording shows the winner over time). It counts who won each cycle; a stop
 * because a request was missing or too old is counted both as a stop and as a stale stop (the
 * monitor also reports the expired read).
 *
 * <p>Run by one thread at a time; {@link #counts()} is thread-safe.
 */
public final class PositionMediatorTask implements Task {

    private final long avoidMaxAgeNs;
    private final long waypointMaxAgeNs;
    private Input<MotionRequest> avoid;
    private Input<MotionRequest> waypoint;
    private Output<VelocityCommand> motor;
    private Output<MediatorDecision> decision;

    // Written only by the task's thread; volatile so that counts() sees them.
    private volatile long obstacleWins;
    private volatile long waypointWins;
    private volatile long stops;
    private volatile long staleStops;
    private volatile long lastStaleStopNs = -1;

    /**
     * @param avoidMaxAgeNs oldest avoider request trusted, in world ns
     * @param waypointMaxAgeNs oldest waypoint request trusted, in world ns
     */
    public PositionMediatorTask(long avoidMaxAgeNs, long waypointMaxAgeNs) {
        this.avoidMaxAgeNs = avoidMaxAgeNs;
        this.waypointMaxAgeNs = waypointMaxAgeNs;
    }

    @Override
    public void initialize(TaskSetup setup) {
        avoid = setup.consume(RobotKeys.MOTION_AVOID, Duration.ofNanos(avoidMaxAgeNs));
        waypoint = setup.consume(RobotKeys.MOTION_WAYPOINT, Duration.ofNanos(waypointMaxAgeNs));
        motor = setup.produce(RobotKeys.MOTOR);
        decision = setup.produce(RobotKeys.MEDIATOR_DECISION);
    }

    @Override
    public void execute(long nowNs) {
        boolean avoidFresh = avoid.hasValue() && !avoid.isExpired();
        boolean waypointFresh = waypoint.hasValue() && !waypoint.isExpired();
        MediatorLogic.Decision d = MediatorLogic.decide(avoidFresh, avoid.value(), waypointFresh, waypoint.value(),
                motor.value());
        switch (d) {
            case OBSTACLE -> obstacleWins++;
            case WAYPOINT -> waypointWins++;
            case IDLE_STOP -> stops++;
            case STALE_STOP -> {
                stops++;
                staleStops++;
                lastStaleStopNs = nowNs;
            }
        }
        motor.publish();
        decision.value().winner = switch (d) {
            case OBSTACLE -> MediatorDecision.OBSTACLE;
            case WAYPOINT -> MediatorDecision.WAYPOINT;
            case IDLE_STOP -> MediatorDecision.IDLE_STOP;
            case STALE_STOP -> MediatorDecision.STALE_STOP;
        };
        decision.publish();
    }

    /**
     * The counts so far; each is current, though they may come from consecutive cycles.
     * Thread-safe; allocates the returned record.
     *
     * @return the counts
     */
    public MediatorCounts counts() {
        return new MediatorCounts(obstacleWins, waypointWins, stops, staleStops, lastStaleStopNs);
    }

    /**
     * Who won the mediator's cycles.
     *
     * @param obstacle cycles the obstacle avoider's request went to the motors
     * @param waypoint cycles the waypoint planner's request went to the motors
     * @param stop cycles that commanded a stop (nobody asked, or a request was stale)
     * @param staleStops of those, the stops because a request was missing or too old
     * @param lastStaleStopNs world time of the last stale stop, or -1 if none
     */
    public record MediatorCounts(long obstacle, long waypoint, long stop, long staleStops, long lastStaleStopNs) {
    }
}
