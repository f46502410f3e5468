package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.OptionalLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ThreadTimerSlackTest {

    @TempDir
    Path proc;

    /** A /proc whose thread-self is thread 456 of process 123, with that thread's slack. */
    private void thread(String slack) throws Exception {
        Files.deleteIfExists(proc.resolve("thread-self"));
        Files.createSymbolicLink(proc.resolve("thread-self"), Path.of("123/task/456"));
        Files.createDirectories(proc.resolve("456"));
        Files.writeString(proc.resolve("456/timerslack_ns"), slack);
    }

    @Test
    void readsTheCallingThreadsSlackFromItsOwnTidAndKeepsTheRange() throws Exception {
        ThreadTimerSlack observed = new ThreadTimerSlack(proc);
        thread("50000\n");
        assertEquals(OptionalLong.of(50_000), observed.observeCurrentThread());
        thread("1\n");
        assertEquals(OptionalLong.of(1), observed.observeCurrentThread());

        assertEquals(OptionalLong.of(50_000), observed.largestNs());
        assertEquals(OptionalLong.of(1), observed.smallestNs());
        assertEquals(2, observed.threads());
    }

    @Test
    void nothingIsCountedWhereProcDoesNotTell() throws Exception {
        ThreadTimerSlack observed = new ThreadTimerSlack(proc);
        assertTrue(observed.observeCurrentThread().isEmpty(), "no thread-self");
        thread("not a number");
        assertTrue(observed.observeCurrentThread().isEmpty(), "unreadable slack");

        assertTrue(observed.largestNs().isEmpty());
        assertTrue(observed.smallestNs().isEmpty());
        assertEquals(0, observed.threads());
    }

    @Test
    void theConditionsCarryTheLargestSlackOrNull() throws Exception {
        MeasuredConditions measured = new MeasuredConditions(10, 0.5, 0.6, 2, 0.01, 0, 0, 0, 0, -1, null, null, 1.0,
                0, 5, 0.5, null, Double.NaN);
        ThreadTimerSlack observed = new ThreadTimerSlack(proc);
        assertEquals(null, measured.withTimerSlack(observed).timerSlackNs(), "no thread observed: not known");
        thread("1");
        observed.observeCurrentThread();
        assertEquals(1L, measured.withTimerSlack(observed).timerSlackNs());
    }
}
