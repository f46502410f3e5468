package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * A behavior's proposal to the position mediator: whether it wants the motors, and the
 * velocity it asks for. Mutable buffer for the data store; not thread-safe.
 */
public final class MotionRequest implements StateValue<MotionRequest> {

    /** true when the behavior asks for control of the motors. */
    public boolean active;
    /** requested forward speed in m/s. */
    public double vxMps;
    /** requested turn rate in rad/s. */
    public double omegaRadPerSec;

    /**
     * Asks for the motors.
     *
     * @param vx forward speed in m/s
     * @param omega turn rate in rad/s
     */
    public void request(double vx, double omega) {
        active = true;
        vxMps = vx;
        omegaRadPerSec = omega;
    }

    /** Asks for nothing. */
    public void release() {
        active = false;
        vxMps = 0;
        omegaRadPerSec = 0;
    }

    @Override
    public void copyFrom(MotionRequest s) {
        active = s.active;
        vxMps = s.vxMps;
        omegaRadPerSec = s.omegaRadPerSec;
    }
}
