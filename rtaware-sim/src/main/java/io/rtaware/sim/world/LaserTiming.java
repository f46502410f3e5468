package io.rtaware.sim.world;

/**
 * When a laser scan's beams are measured and when the scan reaches the client. Immutable.
 *
 * <p>With {@code sweep}, beam {@code i} is measured at {@code start + i * period *
 * angleIncrement / 2 pi}, from wherever the robot is then (the Hokuyo URG-04LX turns at
 * 600 rpm, 100 ms per turn, 1024 steps per turn, and measures its 683 steps 44..725 in about
 * 67 ms: SCIP 2.0 specification, {@code PP} answer {@code SCAN:600}, {@code ARES:1024}); the
 * scan is delivered {@code deliveryDelayNs} after its last beam, stamped with the delivery
 * time, as Player drivers publish a scan when they have read it (a {@code NULL} timestamp in
 * {@code Driver::Publish} means the server's current time). Without {@code sweep}, every beam
 * is measured at the instant the scan is delivered (an ideal, instantaneous sensor).
 *
 * @param sweep true to measure the beams over the turn of the mirror
 * @param deliveryDelayNs from the last beam to delivery, world nanoseconds, not negative
 */
public record LaserTiming(boolean sweep, long deliveryDelayNs) {

    /** Every beam at the instant of delivery. */
    public static final LaserTiming INSTANT = new LaserTiming(false, 0);

    /**
     * The URG-04LX on Player: beams over the 100 ms turn, delivered 10 ms after the last beam
     * (683 x 2 bytes of SCIP data plus line feeds, about 12 ms at 115.2 kbit/s over RS-232,
     * under 2 ms over USB, plus the driver's read; an estimate, not a data-sheet value).
     */
    public static final LaserTiming URG_04LX = new LaserTiming(true, 10_000_000L);

    /**
     * @param sweep true to measure the beams over the turn of the mirror
     * @param deliveryDelayNs from the last beam to delivery, world nanoseconds, not negative
     * @throws IllegalArgumentException if the delay is negative
     */
    public LaserTiming {
        if (deliveryDelayNs < 0) {
            throw new IllegalArgumentException("deliveryDelayNs must not be negative, got " + deliveryDelayNs);
        }
    }
}
