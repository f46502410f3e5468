package io.rtaware.core.task;

import java.util.Objects;

/**
 * A task's declaration that it turns an input into motion and must react before the moving
 * thing it controls covers a given distance: whatever appears in {@code input} at
 * {@code rangeM} must be acted on, and the motion stopped, before it is reached. The core
 * knows nothing of robots; it only checks, after a run, that
 * {@code closingSpeedMps * (period + input age p99) + stoppingDistanceM <= rangeM}
 * ({@link io.rtaware.core.analysis.PeriodAdvisor}'s {@code reaction} rule), where the input's
 * age at a read is {@code inputDelayMs} (how old the data already is when it is committed)
 * plus the time since its last commit (at most one input interval). Immutable and validated.
 *
 * @param input the key the reaction starts from (for example a laser scan)
 * @param speedMps the top speed of the motion, m/s, positive
 * @param stoppingDistanceM distance covered from the moment the task commands a stop until
 *     the motion has stopped (actuator latency plus braking), metres, not negative
 * @param rangeM distance at which the input first shows what must be reacted to, minus any
 *     clearance that must remain (for a robot: sensing range minus the body's extent ahead of
 *     the sensor), metres, positive
 * @param inputDelayMs age of the input's data when it is committed (sensor acquisition and
 *     delivery), milliseconds, not negative
 * @param obstacleSpeedMps how fast what must be reacted to may itself move toward the motion,
 *     m/s, not negative: 0 for things that stand still; above 0 the rule uses the closing speed
 *     {@code speedMps + obstacleSpeedMps} instead of {@code speedMps}
 */
public record ReactionConstraint(String input, double speedMps, double stoppingDistanceM, double rangeM,
                                 double inputDelayMs, double obstacleSpeedMps) {

    /**
     * A reaction to things that stand still.
     *
     * @param input the key the reaction starts from
     * @param speedMps the top speed of the motion, m/s
     * @param stoppingDistanceM stopping distance, metres
     * @param rangeM reaction range, metres
     * @param inputDelayMs the input's age when committed, ms
     */
    public ReactionConstraint(String input, double speedMps, double stoppingDistanceM, double rangeM,
                              double inputDelayMs) {
        this(input, speedMps, stoppingDistanceM, rangeM, inputDelayMs, 0.0);
    }

    /**
     * @param input the key the reaction starts from (for example a laser scan)
     * @param speedMps the top speed of the motion, m/s, positive
     * @param stoppingDistanceM distance covered from the moment the task commands a stop until the motion has
     *     stopped (actuator latency plus braking), metres, not negative
     * @param rangeM distance at which the input first shows what must be reacted to, minus any clearance that
     *     must remain (for a robot: sensing range minus the body's extent ahead of the sensor), metres,
     *     positive
     * @param inputDelayMs age of the input's data when it is committed (sensor acquisition and delivery),
     *     milliseconds, not negative
     * @param obstacleSpeedMps how fast what must be reacted to may itself move toward the motion, m/s, not
     *     negative (0 for things that stand still)
     * @throws IllegalArgumentException naming the field and the value if one is out of range
     */
    public ReactionConstraint {
        Objects.requireNonNull(input, "input");
        if (!(speedMps > 0) || Double.isInfinite(speedMps)) {
            throw new IllegalArgumentException("speedMps must be positive, got " + speedMps);
        }
        if (!(stoppingDistanceM >= 0) || Double.isInfinite(stoppingDistanceM)) {
            throw new IllegalArgumentException("stoppingDistanceM must not be negative, got " + stoppingDistanceM);
        }
        if (!(rangeM > 0) || Double.isInfinite(rangeM)) {
            throw new IllegalArgumentException("rangeM must be positive, got " + rangeM);
        }
        if (!(inputDelayMs >= 0) || Double.isInfinite(inputDelayMs)) {
            throw new IllegalArgumentException("inputDelayMs must not be negative, got " + inputDelayMs);
        }
        if (!(obstacleSpeedMps >= 0) || Double.isInfinite(obstacleSpeedMps)) {
            throw new IllegalArgumentException("obstacleSpeedMps must not be negative, got " + obstacleSpeedMps);
        }
    }

    /** @return the speed at which the gap closes: the motion's own plus the obstacle's, m/s */
    public double closingSpeedMps() {
        return speedMps + obstacleSpeedMps;
    }

    /**
     * @return the assumption the rule makes about the obstacles, in words, for reports: that
     *     they stand still, or that they close at up to {@link #obstacleSpeedMps()}
     */
    public String obstacleAssumption() {
        if (obstacleSpeedMps == 0) {
            return "assumes obstacles stand still: the gap closes at the robot's own speed";
        }
        return String.format(java.util.Locale.ROOT, "assumes obstacles move toward the robot at up to %s m/s: the gap "
                + "closes at %s m/s, and the obstacle does not stop while the robot brakes", trim(obstacleSpeedMps),
                trim(closingSpeedMps()));
    }

    private static String trim(double v) {
        return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
    }

    /**
     * The longest period that still reacts in time, given how old the input is when read.
     *
     * @param inputAgeP99Ms the input's age at a read (p99), milliseconds
     * @return {@code 1000 * (rangeM - stoppingDistanceM) / closingSpeedMps - inputAgeP99Ms}; zero
     *     or less when no period is fast enough
     */
    public double maxPeriodMs(double inputAgeP99Ms) {
        return 1000.0 * (rangeM - stoppingDistanceM) / closingSpeedMps() - inputAgeP99Ms;
    }
}
