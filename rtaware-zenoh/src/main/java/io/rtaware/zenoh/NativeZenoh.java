package io.rtaware.zenoh;

import java.nio.ByteBuffer;

/**
 * The functions of the JNI library ({@code src/main/rust/src/lib.rs}); handles are numbers in the
 * native layer's table of objects (never addresses), 0 for none. A handle used after its close, closed
 * twice, or of the wrong kind makes the call throw a {@link ZenohException}; a close while another
 * thread uses the object (a {@code take} waiting, a {@code put}) is safe: the object lives until
 * that call returns. Only the classes of this package call them, after {@link ZenohLibrary#require()}.
 */
final class NativeZenoh {

    private NativeZenoh() {
    }

    static native long open(String mode, String[] connect, String[] listen, boolean multicastScouting,
                            long connectTimeoutMs) throws ZenohException;

    static native String zid(long session) throws ZenohException;

    static native void close(long session) throws ZenohException;

    static native long declarePublisher(long session, String key) throws ZenohException;

    static native void put(long publisher, ByteBuffer payload, int length, ByteBuffer attachment,
                           int attachmentLength) throws ZenohException;

    static native void undeclarePublisher(long publisher) throws ZenohException;

    static native long newMailbox(int capacity) throws ZenohException;

    static native int take(long mailbox, long timeoutNs, ByteBuffer payload, ByteBuffer attachment, ByteBuffer info)
            throws ZenohException;

    static native long overflowed(long mailbox) throws ZenohException;

    static native void closeMailbox(long mailbox) throws ZenohException;

    static native long declareSubscriber(long session, String key, long mailbox, int channel) throws ZenohException;

    static native void undeclareSubscriber(long subscriber) throws ZenohException;

    static native long declareToken(long session, String key) throws ZenohException;

    static native void undeclareToken(long token) throws ZenohException;

    static native String[] livelinessGet(long session, String key, long timeoutMs, int maxKeys) throws ZenohException;

    static native String[] get(long session, String selector, long timeoutMs, int maxReplies, int maxReplyBytes)
            throws ZenohException;
}
