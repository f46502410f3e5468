package io.rtaware.sim.server;

import io.rtaware.core.time.Clock;
import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.SocketException;
import java.net.SocketTimeoutException;

/**
 * A client's socket input that gives each message a deadline: between messages a read waits as
 * long as it takes (an idle client is fine), but once a read returned the first bytes of a
 * message, the rest must arrive within the timeout, however it trickles in; a later read throws
 * {@link SocketTimeoutException}. The reader calls {@link #messageComplete()} after each
 * message. Reads are passed through unbuffered, so a read never takes bytes of the next
 * message (the frame reader asks for exactly what the message still lacks). Not thread-safe
 * (the client's reader thread only).
 */
final class MessageTimeoutInputStream extends FilterInputStream {

    /** Sets the socket's read timeout ({@link java.net.Socket#setSoTimeout}; 0 = none). */
    interface ReadTimeout {
        void set(int millis) throws SocketException;
    }

    private final ReadTimeout readTimeout;
    private final Clock wallClock;
    private final long timeoutNs;
    private final byte[] one = new byte[1];
    private boolean inMessage;
    private long deadlineNs;
    private int timeoutSetMs = -1;

    /**
     * @param in the socket's stream
     * @param readTimeout how to set the socket's read timeout
     * @param wallClock wall time
     * @param timeoutNs how long a message may take from its first bytes to its last, positive
     */
    MessageTimeoutInputStream(InputStream in, ReadTimeout readTimeout, Clock wallClock, long timeoutNs) {
        super(in);
        this.readTimeout = readTimeout;
        this.wallClock = wallClock;
        this.timeoutNs = timeoutNs;
    }

    /** The message read so far is complete: the next read waits for a new one without a deadline. */
    void messageComplete() {
        inMessage = false;
    }

    @Override
    public int read() throws IOException {
        return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
    }

    @Override
    public int read(byte[] b, int off, int len) throws IOException {
        int waitMs = 0;
        if (inMessage) {
            long leftNs = deadlineNs - wallClock.nanos();
            if (leftNs <= 0) {
                throw new SocketTimeoutException("message not complete within " + timeoutNs / 1_000_000 + " ms");
            }
            waitMs = (int) Math.min(Integer.MAX_VALUE, Math.max(1, (leftNs + 999_999) / 1_000_000));
        }
        if (waitMs != timeoutSetMs) {
            readTimeout.set(waitMs);
            timeoutSetMs = waitMs;
        }
        int n = in.read(b, off, len);
        if (n > 0 && !inMessage) {
            inMessage = true;
            deadlineNs = wallClock.nanos() + timeoutNs;
        }
        return n;
    }
}
