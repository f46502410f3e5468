package io.rtaware.player.protocol;

/**
 * A device address ({@code player_devaddr_t}, 16 bytes on the wire). Over TCP the server
 * ignores {@code host} and {@code robot} in what clients send and fills in its own (host is
 * the raw network-order IPv4 address, robot the port). Immutable and thread-safe.
 *
 * @param host host field (unsigned 32 bits)
 * @param robot robot field, the server's TCP port (unsigned 32 bits)
 * @param interf interface code, see {@link Interfaces}
 * @param index device index
 */
public record DeviceAddress(long host, long robot, int interf, int index) {

    /** Encoded size in bytes. */
    public static final int SIZE_BYTES = 16;

    /**
     * @param interf interface code
     * @param index device index
     * @return the address with host and robot 0
     */
    public static DeviceAddress of(int interf, int index) {
        return new DeviceAddress(0, 0, interf, index);
    }

    /**
     * Parses {@code name:index}, e.g. {@code laser:0}.
     *
     * @param text the device name
     * @return the address with host and robot 0
     * @throws IllegalArgumentException if the interface is unknown or the index is not a
     *     number in 0..65535
     */
    public static DeviceAddress parse(String text) {
        int colon = text.indexOf(':');
        String name = colon < 0 ? text : text.substring(0, colon);
        int code = Interfaces.code(name);
        if (code < 0) {
            throw new IllegalArgumentException("unknown Player interface '" + name + "' in '" + text + "'");
        }
        int index = 0;
        if (colon >= 0) {
            try {
                index = Integer.parseInt(text.substring(colon + 1));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("device index in '" + text + "' is not a number");
            }
        }
        if (index < 0 || index > 0xffff) {
            throw new IllegalArgumentException("device index in '" + text + "' outside 0..65535");
        }
        return of(code, index);
    }

    /**
     * @param other another address
     * @return true if interface and index are equal (host and robot ignored, as the server
     *     does)
     */
    public boolean sameDevice(DeviceAddress other) {
        return interf == other.interf && index == other.index;
    }

    /** @return {@code name:index}, e.g. {@code laser:0} */
    @Override
    public String toString() {
        return Interfaces.name(interf) + ":" + index;
    }
}
