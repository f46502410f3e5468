package io.rtaware.player.protocol;

/**
 * Reply to ranger REQ GET_CONFIG ({@code player_ranger_config_t}, 56 bytes). Immutable and
 * thread-safe.
 *
 * @param minAngleRad bearing of the first beam
 * @param maxAngleRad bearing of the last beam
 * @param angularResRad angular resolution as the server reports it (Stage: fov / samples)
 * @param minRangeM minimum range in metres
 * @param maxRangeM maximum range in metres
 * @param rangeResM range resolution in metres
 * @param frequencyHz scans per second
 */
public record RangerConfig(double minAngleRad, double maxAngleRad, double angularResRad, double minRangeM,
                           double maxRangeM, double rangeResM, double frequencyHz) {
}
