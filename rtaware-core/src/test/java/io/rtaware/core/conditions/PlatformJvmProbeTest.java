package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The pause watch of this very JVM (the test JVM's collector): the time to safepoint is read from
 * the JVM's safepoint log when the watch closes, not streamed while it runs.
 */
class PlatformJvmProbeTest {

    @Test
    void theTimeToSafepointIsKnownAtTheCloseFromTheSafepointLog() {
        JvmProbe.PauseWatch watch = new PlatformJvmProbe().watchPauses();
        System.gc(); // a collection that stops every thread: a safepoint and a pause the log shows

        assertEquals(-1, watch.safepoints(), "while it runs, nothing is streamed: not yet known");
        assertNull(watch.maxTimeToSafepointMs());
        assertEquals("measured when the run ends (the JVM's safepoint log, read at the close)", watch.safepointNote());

        watch.close();
        assertTrue(watch.safepoints() >= 1, "the collection's safepoint, read from the log: "
                + watch.safepoints());
        assertNotNull(watch.maxTimeToSafepointMs());
        assertNull(watch.safepointNote(), "measured");
        assertTrue(watch.gcCount() >= 1, "the collection's pause, from the log: " + watch.gcCount());
        assertTrue(watch.stopsLongerThan(-1) >= 2, "the collection's pause and the safepoint each count as a stop");
    }
}
