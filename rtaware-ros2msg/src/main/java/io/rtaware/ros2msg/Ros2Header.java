package io.rtaware.ros2msg;

/**
 * A {@code std_msgs/msg/Header}: a stamp in nanoseconds and a frame id. Mutable and reused: a
 * decoder overwrites it, an encoder reads it. Not thread-safe.
 */
public final class Ros2Header {

    /** the stamp in nanoseconds since the clock's epoch (world time in rtaware recordings). */
    public long stampNs;
    /** the coordinate frame, e.g. {@code odom}, {@code world}, {@code laser}. */
    public final StringBuilder frameId = new StringBuilder(32);

    /**
     * @param stamp the stamp in ns
     * @param frame the frame id
     * @return this header
     */
    public Ros2Header set(long stamp, CharSequence frame) {
        stampNs = stamp;
        frameId.setLength(0);
        frameId.append(frame);
        return this;
    }
}
