package io.rtaware.sim.world;

import java.util.Locale;
import java.util.Objects;

/**
 * When a laser scan's beams are measured and when the scan reaches the client. Immutable.
 *
 * <p>With {@code sweep}, beam {@code i} is measured at {@code start + i * period *
 * angleIncrement / 2 pi}, from wherever the robot is then (the Hokuyo URG-04LX turns at
 * 600 rpm, 100 ms per turn, 1024 steps per turn, and measures its 683 steps 44..725 in about
 * 67 ms: SCIP 2.0 specification, {@code PP} answer {@code SCAN:600}, {@code ARES:1024}); the
 * scan is delivered {@code deliveryDelayNs} after its last beam, stamped with the delivery
 * time, as Player drivers publish a scan when they have read it (a {@code NULL} timestamp in
 * {@code Driver::Publish} means the server's current time). A sweep starts on the laser's
 * period grid, at the first turn after the previous scan was delivered: a link slower than
 * the turn (the serial link) delivers every second turn. Without {@code sweep}, every beam
 * is measured at the instant the scan is delivered (an ideal, instantaneous sensor).
 *
 * @param sweep true to measure the beams over the turn of the mirror
 * @param deliveryDelayNs from the last beam to delivery, world nanoseconds, not negative
 * @param link how the scan travels to the computer: {@link Link#USB}, {@link Link#SERIAL}, or
 *     {@link Link#NONE} for a delay set by hand or the ideal sensor
 */
public record LaserTiming(boolean sweep, long deliveryDelayNs, Link link) {

    /**
     * The link between the URG-04LX and the computer, and the delivery delay it implies for a
     * full scan of 683 steps in SCIP 2.0's two-character encoding: 1 366 bytes of data, a sum
     * and a line feed after every 64 bytes (22 lines, 44 bytes) and the echo of the command,
     * about 1 430 bytes.
     */
    public enum Link {
        /**
         * USB (full speed, CDC): the 1 430 bytes take well under 2 ms on the bus; 10 ms in all
         * is an estimate of the URG's own transfer preparation and the driver's read, not a
         * data-sheet value.
         */
        USB("usb", 10_000_000L),
        /**
         * RS-232 at 115.2 kbit/s (8N1, 11 520 bytes/s): 1 430 bytes take 124 ms, longer than the
         * 100 ms turn, so scans reach the computer every second turn (5 Hz).
         */
        SERIAL("serial", 124_000_000L),
        /** No link model: the delay was set by hand ({@code laser_delivery_delay_ms}) or the sensor is ideal. */
        NONE("none", 0L);

        private final String jsonName;
        private final long deliveryDelayNs;

        Link(String jsonName, long deliveryDelayNs) {
            this.jsonName = jsonName;
            this.deliveryDelayNs = deliveryDelayNs;
        }

        /** @return the name in reports and scenario files: {@code usb}, {@code serial} or {@code none} */
        public String jsonName() {
            return jsonName;
        }

        /** @return the delivery delay this link implies, world nanoseconds */
        public long deliveryDelayNs() {
            return deliveryDelayNs;
        }

        /**
         * @param name {@code usb} or {@code serial}
         * @return that link
         * @throws IllegalArgumentException naming the value otherwise
         */
        public static Link parse(String name) {
            return switch (name.toLowerCase(Locale.ROOT)) {
                case "usb" -> USB;
                case "serial" -> SERIAL;
                default -> throw new IllegalArgumentException("laser_link must be usb or serial, got '" + name + "'");
            };
        }
    }

    /** Every beam at the instant of delivery. */
    public static final LaserTiming INSTANT = new LaserTiming(false, 0, Link.NONE);

    /** The URG-04LX on Player over USB: beams over the 100 ms turn, delivered 10 ms after the last beam. */
    public static final LaserTiming URG_04LX = urg04lx(Link.USB);

    /**
     * @param sweep true to measure the beams over the turn of the mirror
     * @param deliveryDelayNs from the last beam to delivery, world nanoseconds, not negative
     * @param link how the scan travels to the computer, not null
     * @throws IllegalArgumentException if the delay is negative
     */
    public LaserTiming {
        Objects.requireNonNull(link, "link");
        if (deliveryDelayNs < 0) {
            throw new IllegalArgumentException("deliveryDelayNs must not be negative, got " + deliveryDelayNs);
        }
    }

    /**
     * @param link the link the scans travel over
     * @return the URG-04LX's sweep with that link's delivery delay
     */
    public static LaserTiming urg04lx(Link link) {
        return new LaserTiming(true, link.deliveryDelayNs(), link);
    }
}
