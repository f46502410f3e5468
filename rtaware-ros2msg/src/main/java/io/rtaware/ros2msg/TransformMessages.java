package io.rtaware.ros2msg;

import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarPose;
import io.rtaware.ros2msg.value.PlanarTransform;
import java.util.List;

/**
 * {@code tf2_msgs/msg/TFMessage} of planar transforms (translation x, y; rotation about z), what
 * {@code /tf} and {@code /tf_static} carry, written as CDR without allocating, and read back
 * one {@code geometry_msgs/msg/TransformStamped} at a time. Stateless.
 *
 * <p>Writing: {@link #begin} with the number of transforms, then {@link #transform} that many
 * times. Reading: {@link #count} after {@link CdrReader#wrap}, then {@link #read} that many times.
 */
public final class TransformMessages {

    private TransformMessages() {
    }

    /**
     * Starts a message of {@code count} transforms.
     *
     * @param cdr the buffer (restarted)
     * @param count transforms that follow
     */
    public static void begin(CdrWriter cdr, int count) {
        cdr.begin();
        cdr.writeSequenceLength(count);
    }

    /**
     * Appends one {@code geometry_msgs/msg/TransformStamped}.
     *
     * @param cdr the buffer
     * @param stampNs header stamp in ns since the clock's epoch
     * @param parent the header's frame id
     * @param child the child frame id
     * @param xM translation x in metres
     * @param yM translation y in metres
     * @param yawRad rotation about z in radians
     */
    public static void transform(CdrWriter cdr, long stampNs, CharSequence parent, CharSequence child, double xM,
                                 double yM, double yawRad) {
        Fields.writeTime(cdr, stampNs);
        cdr.writeString(parent);
        cdr.writeString(child);
        Fields.writePlanarPose(cdr, xM, yM, yawRad); // Transform: Vector3 and Quaternion, laid out as a Pose
    }

    /**
     * Writes a whole message of transforms that share one stamp ({@code /tf_static}).
     *
     * @param cdr the buffer (restarted)
     * @param stampNs every transform's header stamp in ns since the clock's epoch
     * @param transforms the transforms
     */
    public static void write(CdrWriter cdr, long stampNs, List<PlanarTransform> transforms) {
        begin(cdr, transforms.size());
        for (int i = 0; i < transforms.size(); i++) { // no iterator: nothing allocated
            PlanarTransform t = transforms.get(i);
            transform(cdr, stampNs, t.parent(), t.child(), t.xM(), t.yM(), t.yawRad());
        }
    }

    /**
     * @param in a reader wrapped around a TFMessage
     * @return how many transforms follow
     * @throws io.rtaware.ros2msg.cdr.CdrException if the message is malformed
     */
    public static int count(CdrReader in) {
        return in.readSequenceLength(4 + 4 + 4 + 4 + 7 * 8);
    }

    /**
     * Reads the next transform: its stamp and parent into {@code header}, its child frame into
     * {@code child}, its planar pose into {@code pose} (the heading from the rotation about z).
     *
     * @param in the reader, after {@link #count}
     * @param header receives the stamp and parent frame
     * @param child receives the child frame (cleared first)
     * @param pose receives x, y and the heading
     * @throws io.rtaware.ros2msg.cdr.CdrException if the message is malformed
     */
    public static void read(CdrReader in, Ros2Header header, StringBuilder child, PlanarPose pose) {
        Fields.readHeader(in, header);
        child.setLength(0);
        in.readString(child);
        Fields.readPlanarPose(in, pose);
    }
}
