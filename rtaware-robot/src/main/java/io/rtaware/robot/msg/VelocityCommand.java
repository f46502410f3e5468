package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * A motor command: forward speed and turn rate (Player position2d CMD VEL). Mutable buffer for
 * the data store; not thread-safe.
 */
public final class VelocityCommand implements StateValue<VelocityCommand> {

    /** forward speed in m/s. */
    public double vxMps;
    /** turn rate in rad/s, counter-clockwise positive. */
    public double omegaRadPerSec;

    /**
     * @param vx forward speed in m/s
     * @param omega turn rate in rad/s
     */
    public void set(double vx, double omega) {
        this.vxMps = vx;
        this.omegaRadPerSec = omega;
    }

    /** @return true if both speeds are exactly zero */
    public boolean isStop() {
        return vxMps == 0.0 && omegaRadPerSec == 0.0;
    }

    @Override
    public void copyFrom(VelocityCommand s) {
        vxMps = s.vxMps;
        omegaRadPerSec = s.omegaRadPerSec;
    }
}
