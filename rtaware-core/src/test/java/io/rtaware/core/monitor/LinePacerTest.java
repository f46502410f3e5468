package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The pacing of one stream of lines, on numbers of nanoseconds given by hand. */
class LinePacerTest {

    private static final long S = 1_000_000_000L;

    @Test
    void theWaitDoublesWhileLinesKeepComingAndStartsOverAfterACalmSpell() {
        LinePacer p = new LinePacer(S, 8 * S);
        assertTrue(p.due(0), "the first line at once");
        assertEquals(0, p.printed(0));
        assertFalse(p.due(S - 1));
        assertEquals(S, p.printed(S));
        assertEquals(2 * S, p.intervalNs());
        assertEquals(2 * S, p.printed(3 * S));
        assertEquals(4 * S, p.printed(7 * S));
        assertEquals(8 * S, p.intervalNs());
        p.printed(15 * S);
        assertEquals(8 * S, p.intervalNs(), "no longer than the longest");
        p.calm();
        assertTrue(p.due(16 * S), "after a calm spell the next line comes at once");
        p.printed(16 * S);
        assertEquals(S, p.intervalNs(), "and the waits start over");
    }

    @Test
    void aFixedRateNeverGrows() {
        LinePacer p = new LinePacer(S, S);
        for (long t = 0; t < 10 * S; t += S) {
            assertTrue(p.due(t));
            p.printed(t);
            assertEquals(S, p.intervalNs());
        }
        assertThrows(IllegalArgumentException.class, () -> new LinePacer(2 * S, S));
    }

    @Test
    void aCalmMomentRecordedLaterCountsOnlyIfALineWasDueThenAndNoneCameAfter() {
        LinePacer p = new LinePacer(S, 8 * S);
        p.printed(0);
        p.printed(S);
        assertEquals(2 * S, p.intervalNs());
        p.calmIfDueAt(2 * S);
        assertEquals(2 * S, p.intervalNs(), "at 2 s no line was due (the wait was 2 s from 1 s): not calm");
        p.calmIfDueAt(3 * S);
        assertEquals(S, p.intervalNs(), "at 3 s a line was due and there was nothing: the wait starts over");
        p.printed(4 * S);
        assertEquals(S, p.intervalNs(), "after a calm spell the next line's wait is the first");
        p.printed(5 * S);
        p.calmIfDueAt(4 * S);
        assertEquals(2 * S, p.intervalNs(), "a moment before the last line says nothing about the wait after it");
    }
}
