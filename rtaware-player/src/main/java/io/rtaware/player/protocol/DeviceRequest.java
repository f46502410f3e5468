package io.rtaware.player.protocol;

/**
 * Body of player REQ DEV and of its replies ({@code player_device_req_t}): subscribe or
 * unsubscribe. In replies {@code access} is the granted access ({@link Subtypes#ACCESS_ERROR}
 * when the driver refused, even inside an ACK) and {@code driverName} the driver. Immutable
 * and thread-safe.
 *
 * @param device the target device
 * @param access access code, see {@link Subtypes#ACCESS_OPEN}
 * @param driverName the driver name ("" in requests)
 */
public record DeviceRequest(DeviceAddress device, int access, String driverName) {
}
