package io.rtaware.player.protocol;

/**
 * Reply to laser REQ GET_CONFIG ({@code player_laser_config_t}, 28 bytes). Immutable and
 * thread-safe.
 *
 * @param minAngleRad bearing of the first beam
 * @param maxAngleRad bearing of the last beam
 * @param resolutionRad angular resolution as the server reports it
 * @param maxRangeM maximum range in metres
 * @param rangeResM range resolution in metres
 * @param intensity intensity flag (0 off)
 * @param scanningFrequencyHz scans per second
 */
public record LaserConfig(float minAngleRad, float maxAngleRad, float resolutionRad, float maxRangeM,
                          float rangeResM, int intensity, float scanningFrequencyHz) {
}
