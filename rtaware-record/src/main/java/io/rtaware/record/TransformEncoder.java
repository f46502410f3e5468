package io.rtaware.record;

import io.rtaware.ros2msg.cdr.CdrWriter;

/**
 * Encodes {@code tf2_msgs/msg/TFMessage} of planar transforms (translation x, y; rotation about
 * z) as CDR, without allocating. Writer thread only.
 */
final class TransformEncoder {

    private static final long NS_PER_S = 1_000_000_000L;

    private TransformEncoder() {
    }

    /**
     * Starts a message of {@code count} transforms.
     *
     * @param cdr the buffer (restarted)
     * @param count transforms that follow
     */
    static void begin(CdrWriter cdr, int count) {
        cdr.begin();
        cdr.writeSequenceLength(count);
    }

    /**
     * Appends one {@code geometry_msgs/msg/TransformStamped}.
     *
     * @param cdr the buffer
     * @param stampNs header stamp, Unix-epoch ns
     * @param parent the header's frame id
     * @param child the child frame id
     * @param xM translation x
     * @param yM translation y
     * @param yawRad rotation about z
     */
    static void transform(CdrWriter cdr, long stampNs, String parent, String child, double xM, double yM,
                          double yawRad) {
        cdr.writeInt32((int) Math.floorDiv(stampNs, NS_PER_S));
        cdr.writeInt32((int) Math.floorMod(stampNs, NS_PER_S));
        cdr.writeString(parent);
        cdr.writeString(child);
        cdr.writeFloat64(xM);
        cdr.writeFloat64(yM);
        cdr.writeFloat64(0);
        cdr.writeFloat64(0);
        cdr.writeFloat64(0);
        cdr.writeFloat64(Math.sin(yawRad / 2));
        cdr.writeFloat64(Math.cos(yawRad / 2));
    }
}
