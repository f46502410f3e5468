package io.rtaware.nav.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.ReactionConstraint;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.nav.logic.ObstacleAvoider;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.RobotKeys;
import java.time.Duration;

/**
 * LaserObstacleAvoidance ({@code obstacle}): consumes {@code laser}, produces
 * {@code motion.avoid} every cycle, from the scan alone (never the position). When the scan is
 * missing or older than its maximum age the avoider cannot see, so it requests control and
 * asks for a stop rather than let the robot drive blind. It declares the reaction it must
 * achieve ({@link ReactionConstraint}: stop within its safety range at the robot's top speed),
 * so the period advice can name its largest safe period.
 *
 * <p>Run by one thread at a time (the monitor's contract); not otherwise thread-safe.
 */
public final class ObstacleAvoidanceTask implements Task {

    private final ObstacleAvoider avoider;
    private final long laserMaxAgeNs;
    private final ReactionConstraint reaction;
    private Input<LaserScan> laser;
    private Output<MotionRequest> request;

    /**
     * @param avoider the decision logic
     * @param laserMaxAgeNs oldest scan trusted, in world ns
     * @param reaction the reaction to declare, or null to declare none
     */
    public ObstacleAvoidanceTask(ObstacleAvoider avoider, long laserMaxAgeNs, ReactionConstraint reaction) {
        this.avoider = avoider;
        this.laserMaxAgeNs = laserMaxAgeNs;
        this.reaction = reaction;
    }

    @Override
    public void initialize(TaskSetup setup) {
        laser = setup.consume(RobotKeys.LASER, Duration.ofNanos(laserMaxAgeNs));
        request = setup.produce(RobotKeys.MOTION_AVOID);
        if (reaction != null) {
            setup.declareReaction(reaction);
        }
    }

    @Override
    public void execute(long nowNs) {
        MotionRequest out = request.value();
        if (!laser.hasValue() || laser.isExpired()) {
            out.request(0, 0);
        } else {
            avoider.decide(laser.value(), out);
        }
        request.publish();
    }
}
