package io.rtaware.player.protocol;

import java.util.Locale;

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

    /**
     * @return what a person reads, e.g. {@code beams -120.0..120.0 deg every 0.352 deg, range 0.02..5.60 m
     *     (resolution 0.001 m), 10.0 Hz}
     */
    @Override
    public String toString() {
        return String.format(Locale.ROOT, "beams %.1f..%.1f deg every %.3f deg, range %.2f..%.2f m (resolution %.3f m),"
                        + " %.1f Hz", Math.toDegrees(minAngleRad), Math.toDegrees(maxAngleRad), Math.toDegrees(angularResRad),
                minRangeM, maxRangeM, rangeResM, frequencyHz);
    }
}
