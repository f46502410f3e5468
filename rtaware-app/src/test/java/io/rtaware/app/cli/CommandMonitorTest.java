package io.rtaware.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The commands' termination handler: what it throws makes the command's exit status non-zero. */
class CommandMonitorTest {

    private static final long MS = 1_000_000L;

    /** Does nothing each cycle. */
    private static final class Idle implements Task {
        @Override
        public void initialize(TaskSetup setup) {
        }

        @Override
        public void execute(long nowNs) {
        }
    }

    @Test
    void aReportThatCannotBeFinishedIsAFailedStepNotStatusZero() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        OutputWrites writes = new OutputWrites(new PrintStream(err, true, StandardCharsets.UTF_8));
        Monitor monitor = Monitor.builder(new ManualClock()).task("t", Schedule.periodic(10 * MS), new Idle()).build();
        CommandMonitor.onTermination(monitor, writes, report -> {
            throw new OutOfMemoryError("Java heap space");
        });
        monitor.startStepped().runFor(20 * MS);
        monitor.stop();

        assertEquals(0, monitor.frameworkErrors(), "the command's own failure, not the framework's");
        assertEquals(1, writes.exitStatus(0));
        assertTrue(err.toString(StandardCharsets.UTF_8).startsWith(
                "rtaware: could not finish the run's report: java.lang.OutOfMemoryError: Java heap space"), err.toString());
    }

    @Test
    void aReportFinishedWholeKeepsTheStatus() {
        OutputWrites writes = new OutputWrites(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        Monitor monitor = Monitor.builder(new ManualClock()).task("t", Schedule.periodic(10 * MS), new Idle()).build();
        int[] finished = new int[1];
        CommandMonitor.onTermination(monitor, writes, report -> finished[0]++);
        monitor.startStepped().runFor(20 * MS);
        monitor.stop();

        assertEquals(1, finished[0]);
        assertEquals(0, writes.exitStatus(0));
    }
}
