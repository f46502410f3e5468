package io.rtaware.robot.validate;

/**
 * Thrown by a robot data task (Player's or ROS 2's) in the cycle in which it halted the robot
 * because a device or topic sent only samples that cannot be true for a second of world time
 * ({@link RejectionWatch}). The message is one
 * line naming the device and the offending value.
 */
public final class ImpossibleDataException extends Exception {

    private static final long serialVersionUID = 1L;

    /** @param message the device, the value, and that the robot was halted */
    public ImpossibleDataException(String message) {
        super(message);
    }
}
