package io.rtaware.zenoh;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * An open Zenoh session. Declarations made through it belong to it and are undeclared by
 * {@link #close()} if their owners did not close them first. Thread-safe (Zenoh sessions are);
 * {@link #close()} may race with the use of its publishers and mailboxes, which then throw a
 * {@link ZenohException} (or a waiting {@code take} returns {@code CLOSED}).
 */
public final class ZenohSession implements AutoCloseable {

    /** The most liveliness keys {@link #livelinessKeys(String, long)} takes: a large ROS 2 graph's tokens, about 2 MB of keys. */
    public static final int MAX_LIVELINESS_KEYS = 10_000;

    private final Object lock = new Object();
    private final List<AutoCloseable> owned = new ArrayList<>();
    private final ZenohConfig config;
    private final String zid;
    private long handle;

    private ZenohSession(ZenohConfig config, long handle, String zid) {
        this.config = config;
        this.handle = handle;
        this.zid = zid;
    }

    /**
     * Opens a session.
     *
     * @param config how
     * @return the session
     * @throws ZenohException if the native layer is missing, or no connect endpoint is reachable
     *     in time, or a listen endpoint cannot be bound
     */
    public static ZenohSession open(ZenohConfig config) throws ZenohException {
        Objects.requireNonNull(config, "config");
        ZenohLibrary.require();
        long h = NativeZenoh.open(config.mode().name().toLowerCase(java.util.Locale.ROOT),
                config.connect().toArray(String[]::new), config.listen().toArray(String[]::new),
                config.multicastScouting(), config.connectTimeoutMs());
        try {
            return new ZenohSession(config, h, NativeZenoh.zid(h));
        } catch (ZenohException | RuntimeException e) {
            NativeZenoh.close(h);
            throw e;
        }
    }

    /** @return the session's Zenoh id as Zenoh prints it (lowercase hexadecimal) */
    public String zid() {
        return zid;
    }

    /** @return the configuration it was opened with */
    public ZenohConfig config() {
        return config;
    }

    /**
     * @param key the key expression to publish on
     * @return a publisher
     * @throws ZenohException if the key expression is invalid or the session is closed
     */
    public ZenohPublisher declarePublisher(String key) throws ZenohException {
        synchronized (lock) {
            ZenohPublisher p = new ZenohPublisher(this, key, NativeZenoh.declarePublisher(open(), key));
            owned.add(p);
            return p;
        }
    }

    /**
     * @param capacity samples kept when the reader falls behind (the oldest are dropped first)
     * @return a mailbox to which subscribers of this session can deliver
     * @throws ZenohException if the session is closed
     */
    public ZenohMailbox newMailbox(int capacity) throws ZenohException {
        synchronized (lock) {
            open();
            ZenohMailbox m = new ZenohMailbox(this, NativeZenoh.newMailbox(capacity));
            owned.add(m);
            return m;
        }
    }

    long declareSubscriber(String key, long mailbox, int channel) throws ZenohException {
        synchronized (lock) {
            return NativeZenoh.declareSubscriber(open(), key, mailbox, channel);
        }
    }

    /**
     * Declares a liveliness token: others see it with a liveliness query or subscription until
     * it is closed or the session ends.
     *
     * @param key the token's key expression
     * @return the token
     * @throws ZenohException if the key expression is invalid or the session is closed
     */
    public LivelinessToken declareToken(String key) throws ZenohException {
        synchronized (lock) {
            LivelinessToken t = new LivelinessToken(this, key, NativeZenoh.declareToken(open(), key));
            owned.add(t);
            return t;
        }
    }

    /**
     * At most {@value #MAX_LIVELINESS_KEYS} keys: {@link #livelinessKeys(String, long, int)}.
     *
     * @param keyPattern a key expression, wildcards allowed ({@code @ros2_lv/0/**})
     * @param timeoutMs how long to collect replies
     * @return the keys of the liveliness tokens alive now that match, in no particular order
     * @throws ZenohException if the pattern is invalid, the session is closed, or more than
     *     {@value #MAX_LIVELINESS_KEYS} tokens match
     */
    public List<String> livelinessKeys(String keyPattern, long timeoutMs) throws ZenohException {
        return livelinessKeys(keyPattern, timeoutMs, MAX_LIVELINESS_KEYS);
    }

    /**
     * The keys of the liveliness tokens that match, as many as the network answers up to a
     * bound: how many there are is for other processes to choose, so more than {@code maxKeys}
     * is an error (the query stops reading there), not an allocation without end.
     *
     * @param keyPattern a key expression, wildcards allowed ({@code @ros2_lv/0/**})
     * @param timeoutMs how long to collect replies
     * @param maxKeys the most keys taken (non-negative)
     * @return the keys of the liveliness tokens alive now that match, in no particular order
     * @throws ZenohException if the pattern is invalid, the session is closed, or more than
     *     {@code maxKeys} tokens match (naming the pattern)
     * @throws IllegalArgumentException if {@code maxKeys} is negative
     */
    public List<String> livelinessKeys(String keyPattern, long timeoutMs, int maxKeys) throws ZenohException {
        if (maxKeys < 0) {
            throw new IllegalArgumentException("maxKeys must not be negative: " + maxKeys);
        }
        long h;
        synchronized (lock) {
            h = open();
        }
        return List.of(NativeZenoh.livelinessGet(h, keyPattern, timeoutMs, maxKeys));
    }

    /**
     * One reply to a query.
     *
     * @param key the key it answers for
     * @param text its payload read as UTF-8 (bytes that are not UTF-8 replaced)
     */
    public record Reply(String key, String text) {
    }

    /**
     * Asks the queryables whose key expressions match {@code selector} (an admin space, say) and
     * collects their answers, bounded as {@link #livelinessKeys(String, long, int)} is: more than
     * {@code maxReplies} replies, or one larger than {@code maxReplyBytes}, is an error, not an
     * allocation without end. Replies that are errors are left out.
     *
     * @param selector a key expression, wildcards allowed
     * @param timeoutMs how long to wait for the replies
     * @param maxReplies the most replies taken (non-negative)
     * @param maxReplyBytes the largest payload of one reply (non-negative)
     * @return the replies, in the order they arrived
     * @throws ZenohException if the selector is invalid, the session is closed, or the replies
     *     break a bound (naming the selector)
     * @throws IllegalArgumentException if a bound is negative
     */
    public List<Reply> get(String selector, long timeoutMs, int maxReplies, int maxReplyBytes) throws ZenohException {
        if (maxReplies < 0 || maxReplyBytes < 0) {
            throw new IllegalArgumentException("maxReplies " + maxReplies + " and maxReplyBytes " + maxReplyBytes
                    + " must not be negative");
        }
        long h;
        synchronized (lock) {
            h = open();
        }
        String[] flat = NativeZenoh.get(h, selector, timeoutMs, maxReplies, maxReplyBytes);
        List<Reply> replies = new ArrayList<>(flat.length / 2);
        for (int i = 0; i + 1 < flat.length; i += 2) {
            replies.add(new Reply(flat[i], flat[i + 1]));
        }
        return List.copyOf(replies);
    }

    void forget(AutoCloseable declaration) {
        synchronized (lock) {
            owned.remove(declaration);
        }
    }

    private long open() throws ZenohException {
        if (handle == 0) {
            throw new ZenohException("the Zenoh session is closed");
        }
        return handle;
    }

    /**
     * Closes what is still declared, then the session. Idempotent.
     *
     * @throws ZenohException the first failure, after every step was attempted
     */
    @Override
    public void close() throws ZenohException {
        List<AutoCloseable> left;
        synchronized (lock) {
            if (handle == 0) {
                return;
            }
            left = new ArrayList<>(owned);
        }
        ZenohException first = null;
        for (int i = left.size() - 1; i >= 0; i--) {
            try {
                left.get(i).close();
            } catch (Exception e) {
                first = first == null ? new ZenohException(e.getMessage()) : first;
            }
        }
        synchronized (lock) {
            long h = handle;
            handle = 0;
            owned.clear();
            try {
                if (h != 0) { // 0: a concurrent close got here first
                    NativeZenoh.close(h);
                }
            } catch (ZenohException e) {
                first = first == null ? e : first;
            }
        }
        if (first != null) {
            throw first;
        }
    }
}
