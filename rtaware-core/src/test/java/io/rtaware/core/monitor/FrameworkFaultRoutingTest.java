package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import java.io.OutputStream;
import java.io.PrintStream;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * Issue 38, one loop contract: what the framework used to print to stderr itself (a thread that
 * did not return at stop, a task whose {@code terminate()} threw, a fault of the console
 * reporter's printer) goes to the monitor's {@link FrameworkErrorHandler} and is counted in
 * {@link Monitor#frameworkErrors()}.
 */
class FrameworkFaultRoutingTest {

    private static final long MS = 1_000_000L;

    /** What a handler received, "source: message". */
    private final List<String> received = new CopyOnWriteArrayList<>();
    private final CountDownLatch first = new CountDownLatch(1);
    private final FrameworkErrorHandler handler = (source, error) -> {
        received.add(source + ": " + error.getMessage());
        first.countDown();
    };

    /** A task that does nothing. */
    private static class Idle implements Task {
        @Override
        public void initialize(TaskSetup setup) {
        }

        @Override
        public void execute(long nowNs) {
        }
    }

    @Test
    void aThreadThatDoesNotReturnAtStopIsAFaultBeforeItIsInterrupted() throws Exception {
        FrameworkFaults faults = new FrameworkFaults(handler);
        CountDownLatch interrupted = new CountDownLatch(1);
        Thread stuck = new Thread(() -> {
            try {
                new CountDownLatch(1).await(); // returns only when interrupted
            } catch (InterruptedException e) {
                interrupted.countDown(); // what the stop's interrupt is for
            }
        }, "stuck-task");
        stuck.start();
        Watchdog.joinOrInterrupt(stuck, 1, faults);
        // The second join is as short as the first: on a busy machine the thread may still be
        // ending. That it was interrupted is what counts; the latch says so without a margin.
        assertTrue(interrupted.await(30, TimeUnit.SECONDS), "interrupted by the stop");
        stuck.join();
        assertEquals(List.of("stop: stuck-task did not return within 1 ms of stop; interrupting it"), received);
        assertEquals(1, faults.count());
    }

    @Test
    void aTaskWhoseTerminateThrowsIsAFrameworkFault() {
        Monitor monitor = Monitor.builder(new ManualClock()).errorHandler(handler)
                .task("leaky", Schedule.periodic(10 * MS), new Idle() {
                    @Override
                    public void terminate() {
                        throw new IllegalStateException("the port was closed already");
                    }
                }).build();
        monitor.startStepped().runFor(20 * MS);
        monitor.stop();
        assertEquals(List.of("terminate() of task 'leaky': the port was closed already"), received);
        assertEquals(1, monitor.frameworkErrors());
    }

    @Test
    void aFaultOfTheConsoleReportersPrinterGoesToTheMonitorItListensTo() throws Exception {
        Monitor monitor = Monitor.builder(new ManualClock()).errorHandler(handler)
                .task("planner", Schedule.periodic(10 * MS), new Idle()).build();
        PrintStream brokenTerminal = new PrintStream(new OutputStream() {
            @Override
            public void write(int b) {
                throw new IllegalStateException("the terminal is gone");
            }
        });
        ConsoleReporter reporter = new ConsoleReporter(brokenTerminal, monitor.tasks(), false, new ManualClock(), true);
        monitor.addListener(reporter);
        monitor.startStepped();
        try {
            reporter.onDeadlineMiss(monitor.tasks().get(0), 0, 10 * MS, 15 * MS, true); // a line for the printer
            assertTrue(first.await(60, TimeUnit.SECONDS), "the printer's fault reached the monitor's handler");
            assertEquals(List.of("console reporter: the terminal is gone"), received);
            assertEquals(1, monitor.frameworkErrors());
        } finally {
            reporter.close();
            monitor.stop();
        }
    }
}
