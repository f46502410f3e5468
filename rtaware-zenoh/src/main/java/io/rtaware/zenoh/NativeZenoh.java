package io.rtaware.zenoh;

import java.nio.ByteBuffer;

/**
 * The functions of the JNI library ({@code src/main/rust/src/lib.rs}); handles are addresses of
 * Rust objects, 0 for none. Only the classes of this package call them, after
 * {@link ZenohLibrary#require()}.
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

    static native String[] livelinessGet(long session, String key, long timeoutMs) throws ZenohException;
}
