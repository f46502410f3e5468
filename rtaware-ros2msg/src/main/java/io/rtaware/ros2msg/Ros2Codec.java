package io.rtaware.ros2msg;

import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;

/**
 * Encodes a value of rtaware as one ROS 2 message in CDR, and decodes such a message back into
 * a value. Neither direction allocates in steady state (strings outside ASCII excepted).
 * Implementations hold no state between calls unless they say so.
 *
 * @param <T> the rtaware value type
 */
public interface Ros2Codec<T> {

    /** @return the ROS 2 type this codec speaks */
    Ros2MessageType type();

    /**
     * Writes a whole message, encapsulation header included (calls {@link CdrWriter#begin()}).
     *
     * @param header stamp and frame id (ignored by types without a header)
     * @param value the value
     * @param out the writer; the message is {@code out.buffer()[0 .. out.size())}
     * @throws io.rtaware.ros2msg.cdr.CdrException if the message does not fit
     */
    void encode(Ros2Header header, T value, CdrWriter out);

    /**
     * Reads a whole message from a wrapped reader into {@code into}.
     *
     * @param in a reader positioned after the encapsulation header ({@link CdrReader#wrap})
     * @param header receives stamp and frame id (left alone by types without a header)
     * @param into receives the value
     * @throws io.rtaware.ros2msg.cdr.CdrException if the message is malformed or exceeds {@code into}'s capacity
     */
    void decode(CdrReader in, Ros2Header header, T into);
}
