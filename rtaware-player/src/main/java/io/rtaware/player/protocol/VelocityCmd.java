package io.rtaware.player.protocol;

/**
 * Body of position2d CMD VEL ({@code player_position2d_cmd_vel_t}, 28 bytes). Immutable and
 * thread-safe.
 *
 * @param vxMps forward speed in m/s
 * @param vyMps sideways speed in m/s
 * @param omegaRadPerSec turn rate in rad/s
 * @param state motor state (1 = on, as libplayerc sends)
 */
public record VelocityCmd(double vxMps, double vyMps, double omegaRadPerSec, int state) {
}
