package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * Issue 24: a SIGKILLed experiment left its run writing into the folder. A run ends when the
 * process named as its experiment ends. Real processes stand in for the experiment; the wait for
 * the end is bounded, never a timing assumption.
 */
class ExperimentParentWatchTest {

    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final PrintStream errStream = new PrintStream(err, true, StandardCharsets.UTF_8);

    @Test
    void aRunExitsWhenItsExperimentIsKilled() throws Exception {
        Process experiment = new ProcessBuilder("sleep", "60").start();
        CompletableFuture<Integer> exit = new CompletableFuture<>();
        try {
            assertTrue(ExperimentParentWatch.start(Long.toString(experiment.pid()), errStream, exit::complete));
            assertFalse(exit.isDone(), "the experiment is alive: the run goes on");
            experiment.destroyForcibly(); // SIGKILL: nothing of the experiment runs after it
            assertEquals(ExperimentParentWatch.EXIT_PARENT_GONE, exit.get(30, TimeUnit.SECONDS));
        } finally {
            experiment.destroyForcibly().waitFor();
        }
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("(pid " + experiment.pid() + ") is gone; stopping the robot"),
                err.toString(StandardCharsets.UTF_8));
    }

    @Test
    void aRunWhoseExperimentIsGoneAlreadyExitsAtOnce() throws Exception {
        Process experiment = new ProcessBuilder("true").start();
        experiment.waitFor();
        int[] status = {-1};
        assertTrue(ExperimentParentWatch.start(Long.toString(experiment.pid()), errStream, s -> status[0] = s));
        assertEquals(ExperimentParentWatch.EXIT_PARENT_GONE, status[0]);
    }

    @Test
    void aRunOutsideAnExperimentWatchesNothing() {
        assertFalse(ExperimentParentWatch.start(null, errStream, s -> {
            throw new AssertionError("no exit");
        }));
        assertFalse(ExperimentParentWatch.start("not-a-pid", errStream, s -> {
            throw new AssertionError("no exit");
        }));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("'not-a-pid' is not a pid"));
    }
}
