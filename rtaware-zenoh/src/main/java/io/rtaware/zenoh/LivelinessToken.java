package io.rtaware.zenoh;

/** A declared liveliness token. Thread-safe. */
public final class LivelinessToken implements AutoCloseable {

    private final ZenohSession session;
    private final String key;
    private long handle;

    LivelinessToken(ZenohSession session, String key, long handle) {
        this.session = session;
        this.key = key;
        this.handle = handle;
    }

    /** @return the token's key expression */
    public String key() {
        return key;
    }

    /** Undeclares the token. Idempotent. */
    @Override
    public synchronized void close() throws ZenohException {
        if (handle == 0) {
            return;
        }
        long h = handle;
        handle = 0;
        session.forget(this);
        NativeZenoh.undeclareToken(h);
    }
}
