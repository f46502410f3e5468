package io.rtaware.record;

import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;

/**
 * The CDR of {@code rtaware_msgs/msg/StateJson} ({@code string key}, {@code string json}): a
 * committed value as the JSON of its fields, on the channels whose metadata says
 * {@value #VALUE_ENCODING}{@code =}{@value #JSON}.
 */
public final class StateJsonMessage {

    /** Channel metadata naming how a key's value is carried in its messages. */
    public static final String VALUE_ENCODING = "value_encoding";
    /** {@link #VALUE_ENCODING} of channels whose messages carry the value as JSON in a StateJson. */
    public static final String JSON = "json";

    private StateJsonMessage() {
    }

    /**
     * Encodes without allocating (the writer thread).
     *
     * @param cdr the buffer (restarted)
     * @param key the key's name
     * @param json UTF-8 JSON
     * @param length its bytes
     */
    static void encode(CdrWriter cdr, String key, byte[] json, int length) {
        cdr.begin();
        cdr.writeString(key);
        cdr.writeInt32(length + 1);
        for (int i = 0; i < length; i++) {
            cdr.writeInt8(json[i]);
        }
        cdr.writeInt8(0);
    }

    /**
     * @param data a buffer holding the message
     * @param offset its first byte
     * @param length its bytes
     * @return the JSON's UTF-8 bytes
     * @throws CdrException if the message is malformed
     */
    public static byte[] json(byte[] data, int offset, int length) {
        CdrReader r = new CdrReader().wrap(data, offset, length);
        r.skipString();
        long n = r.readInt32() & 0xffffffffL;
        if (n < 1 || n > r.remaining()) {
            throw new CdrException("StateJson json length " + n + " invalid with " + r.remaining() + " bytes left");
        }
        byte[] json = new byte[(int) n - 1];
        r.readBytes(json, 0, json.length);
        if (r.readInt8() != 0) {
            throw new CdrException("StateJson json is not NUL-terminated");
        }
        return json;
    }
}
