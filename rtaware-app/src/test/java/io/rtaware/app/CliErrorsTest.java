package io.rtaware.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** User errors end with exit status 2 and exactly one line on stderr, never a stack trace. */
class CliErrorsTest {

    private static String[] runCapturingErr(String... args) {
        PrintStream saved = System.err;
        ByteArrayOutputStream buffer = new ByteArrayOutputStream();
        System.setErr(new PrintStream(buffer, true, StandardCharsets.UTF_8));
        int status;
        try {
            status = RtawareCli.execute(args);
        } finally {
            System.setErr(saved);
        }
        return new String[] {Integer.toString(status), buffer.toString(StandardCharsets.UTF_8)};
    }

    private static void assertOneLineUserError(String[] result, String expectedFragment) {
        assertEquals("2", result[0], "exit status of a user error");
        String err = result[1].strip();
        assertEquals(1, err.lines().count(), "exactly one line on stderr, got:\n" + err);
        assertTrue(err.contains(expectedFragment), "message names the problem: " + err);
        assertTrue(!err.contains("\tat "), "no stack trace: " + err);
    }

    @Test
    void badPeriodInBenchIsOneLineWithStatus2() {
        assertOneLineUserError(runCapturingErr("bench", "--period", "fast"), "'fast' is not a duration");
    }

    @Test
    void zeroPeriodInSpecIsOneLineWithStatus2() {
        assertOneLineUserError(runCapturingErr("bench", "--spec", "a:0ms:1ms"), "period of task 'a' must be positive");
    }

    @Test
    void nonPositiveTimeScaleIsOneLineWithStatus2InEveryCommand() {
        for (String command : new String[] {"run", "bench", "sim", "experiment"}) {
            assertOneLineUserError(runCapturingErr(command, "--time-scale", "0"), "'0' is not a time scale");
            assertOneLineUserError(runCapturingErr(command, "--time-scale", "fast"), "'fast' is not a time scale");
        }
    }

    @Test
    void exportWithACompareOrASweepIsOneLineWithStatus2() {
        // a comparison runs several executors in turn: there is no one monitor to export
        assertOneLineUserError(runCapturingErr("bench", "--compare", "--export"), "--compare takes --tasks");
        assertOneLineUserError(runCapturingErr("bench", "--sweep-tasks", "10,100", "--export"), "or --export)");
    }

    @Test
    void simLimitsOutOfRangeAreOneLineWithStatus2() {
        assertOneLineUserError(runCapturingErr("sim", "--max-clients", "0"), "--max-clients must be 1..4096, got 0");
        assertOneLineUserError(runCapturingErr("sim", "--max-rules", "-3"), "--max-rules must be 1..65536, got -3");
        assertOneLineUserError(runCapturingErr("sim", "--message-timeout", "90min"), "--message-timeout must be 1ms..60min, got ");
    }

    @Test
    void unknownExecutorAndBadSweepAreOneLineWithStatus2() {
        assertOneLineUserError(runCapturingErr("bench", "--executor", "fibers"), "--executor must be threaded or pooled, got fibers");
        assertOneLineUserError(runCapturingErr("bench", "--executor", "pooled", "--workers", "0"), "--workers must be 1 to 4 (");
        assertOneLineUserError(runCapturingErr("bench", "--sweep-tasks", "10,0"), "--sweep-tasks needs task counts of at least 1");
    }

    @Test
    void unknownOptionIsOneLineWithStatus2() {
        assertOneLineUserError(runCapturingErr("bench", "--frobnicate"), "--frobnicate");
    }
}
