package io.rtaware.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import picocli.CommandLine;

/**
 * Runs one command line in this JVM with stdout and stderr captured, for tests of what a user
 * sees: the exit status and the lines printed.
 *
 * @param status the exit status
 * @param out what went to stdout
 * @param err what went to stderr
 */
public record CliRun(int status, String out, String err) {

    /**
     * @param args the command line
     * @return what happened
     */
    public static CliRun of(String... args) {
        return of(CommandLine.defaultFactory(), args);
    }

    /**
     * @param factory makes the command objects (e.g. with a small memory budget)
     * @param args the command line
     * @return what happened
     */
    public static synchronized CliRun of(CommandLine.IFactory factory, String... args) {
        PrintStream savedOut = System.out;
        PrintStream savedErr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status;
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            status = RtawareCli.execute(factory, args);
        } finally {
            System.setOut(savedOut);
            System.setErr(savedErr);
        }
        return new CliRun(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    /**
     * Asserts a user error: status 2, exactly one line on stderr containing the fragment, no stack trace.
     *
     * @param fragment what the line must say
     * @return this
     */
    public CliRun assertOneLineUserError(String fragment) {
        // Once a @FuzzTest has run in this JVM, Jazzer's agent logs each class it instruments on stderr
        // ("INFO: Instrumented io.rtaware... with custom hooks only"): not the command's output.
        String e = err.lines().filter(l -> !l.startsWith("INFO: Instrumented ")).reduce((a, b) -> a + "\n" + b)
                .orElse("").strip();
        assertEquals(2, status, "exit status of a user error; stderr:\n" + err + "\nstdout:\n" + out);
        assertEquals(1, e.lines().count(), "exactly one line on stderr, got:\n" + e);
        assertTrue(e.contains(fragment), "the line names the problem (" + fragment + "): " + e);
        assertFalse(e.contains("\tat ") || e.contains("Exception in"), "no stack trace: " + e);
        return this;
    }
}
