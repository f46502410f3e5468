package io.rtaware.player.protocol;

/**
 * Body of player REQ DRIVERINFO and its reply ({@code player_device_driverinfo_t}).
 * Immutable and thread-safe.
 *
 * @param device the device asked about
 * @param driverName its driver ("" in requests)
 */
public record DriverInfo(DeviceAddress device, String driverName) {
}
