package io.rtaware.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.core.time.ManualClock;
import java.io.IOException;
import java.io.InputStream;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The per-message deadline on a manual clock: exact, without sockets or sleeps. */
class MessageTimeoutInputStreamTest {

    private static final long S = 1_000_000_000L;

    /** Delivers one byte per read, each after {@code stepNs} of (manual) time. */
    private static InputStream trickle(ManualClock clock, long stepNs) {
        return new InputStream() {
            @Override
            public int read() {
                clock.advance(stepNs);
                return 7;
            }
        };
    }

    @Test
    void aTricklingMessageTimesOutAtItsDeadlineAndTheNextMessageWaitsFreely() throws IOException {
        ManualClock clock = new ManualClock();
        List<Integer> timeoutsMs = new ArrayList<>();
        MessageTimeoutInputStream in = new MessageTimeoutInputStream(trickle(clock, 3 * S), timeoutsMs::add, clock,
                10 * S);
        byte[] b = new byte[40];
        for (int i = 0; i < 5; i++) { // bytes at 3, 6, 9, 12, 15 s; the deadline is 3 + 10 s
            assertEquals(1, in.read(b, i, 1));
        }
        assertEquals(List.of(0, 10_000, 7_000, 4_000, 1_000), timeoutsMs,
                "no timeout between messages, then what is left of the message's 10 s");
        SocketTimeoutException e = assertThrows(SocketTimeoutException.class, () -> in.read(b, 5, 1));
        assertEquals("message not complete within 10000 ms", e.getMessage());

        in.messageComplete();
        timeoutsMs.clear();
        assertEquals(1, in.read(b, 0, 1));
        assertEquals(List.of(0), timeoutsMs, "a new message: the first read waits without a timeout");
    }
}
