package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.FnTask;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * A fault on the framework's side (a listener, a termination handler) never stops a task thread
 * or the watchdog: it is counted and handed to the one error handler, and the task keeps its
 * exact timing. The first test is the case of issue 13: a listener that throws on its third call
 * to a 10 ms task killed the task thread, and the report said all was well.
 */
class ContainedFaultsTest {

    private final ManualClock clock = new ManualClock();
    private final List<String> handled = new CopyOnWriteArrayList<>();

    /** Throws on its third onCycle call, and only then. */
    private static final class ThirdCallThrows implements MonitorListener {
        final AtomicInteger calls = new AtomicInteger();

        @Override
        public void onCycle(TaskInfo task, long releaseNs, long startNs, long endNs) {
            if (calls.incrementAndGet() == 3) {
                throw new IllegalStateException("listener bug");
            }
        }
    }

    private Monitor tickWith(MonitorListener listener) {
        return Monitor.builder(clock).listener(listener)
                .errorHandler((source, error) -> handled.add(source + ": " + error.getMessage()))
                .task("tick", Schedule.periodic(ms(10)), FnTask.of(now -> { })).build();
    }

    @Test
    void aListenerThatThrowsOnItsThirdCallDoesNotStopTheTaskThread() {
        ThirdCallThrows listener = new ThirdCallThrows();
        Monitor monitor = tickWith(listener);
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(300));
        assertEquals(TaskState.RUNNING, monitor.tasks().stream().map(t -> ((TaskRuntime) t).state()).findFirst()
                .orElseThrow(), "the task is still running");
        Report report = monitor.stop();

        TaskReport tick = report.task("tick");
        assertEquals(30, tick.releases(), "releases at 0, 10, ..., 290 ms");
        assertEquals(30, tick.runs(), "every release ran");
        assertEquals(0, tick.misses(), "no miss");
        assertEquals(0, tick.errors(), "the task itself never failed");
        assertEquals(1, tick.listenerErrors(), "the listener's fault is counted on the task");
        assertEquals(1, report.frameworkErrors(), "and in the run's framework errors");
        assertEquals(30, listener.calls.get(), "the listener kept being called after its fault");
        assertEquals(List.of("listener " + ThirdCallThrows.class.getName() + ".onCycle on task 'tick': listener bug"),
                handled, "one call of the error handler, naming the listener, the event and the task");
    }

    @Test
    void theSameOnTheStepExecutor() {
        ThirdCallThrows listener = new ThirdCallThrows();
        Monitor monitor = tickWith(listener);
        monitor.startStepped().runUntil(ms(300));
        Report report = monitor.stop();

        assertEquals(30, report.task("tick").releases());
        assertEquals(30, report.task("tick").runs());
        assertEquals(0, report.task("tick").misses());
        assertEquals(1, report.task("tick").listenerErrors());
        assertEquals(1, handled.size());
    }

    @Test
    void aListenerThatThrowsOnTheWatchdogThreadDoesNotStopTheWatchdog() {
        AtomicInteger missCalls = new AtomicInteger();
        MonitorListener missThrows = new MonitorListener() {
            @Override
            public void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedNs,
                                       boolean stillRunning) {
                missCalls.incrementAndGet();
                throw new IllegalStateException("miss listener bug");
            }
        };
        AtomicInteger cycle = new AtomicInteger();
        Monitor monitor = Monitor.builder(clock).listener(missThrows)
                .errorHandler((source, error) -> handled.add(source))
                .task("slow", Schedule.periodic(ms(10)), FnTask.of(now -> {
                    // Cycles 0 and 3 run 15 ms: each misses its deadline and skips one release.
                    int c = cycle.getAndIncrement();
                    if (c == 0 || c == 3) {
                        clock.advance(ms(15));
                    }
                })).build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(100));
        Report report = monitor.stop();

        TaskReport slow = report.task("slow");
        // Releases 0..9 (0..90 ms): 1 and 5 were skipped, 8 ran.
        assertEquals(10, slow.releases());
        assertEquals(8, slow.runs());
        assertEquals(2, slow.skipped());
        assertEquals(4, slow.misses(), "two late cycles plus two skipped releases");
        assertEquals(2, missCalls.get(), "both misses reached the listener: the watchdog survived the first");
        assertEquals(2, slow.listenerErrors());
        assertEquals(2, handled.size());
    }

    @Test
    void aTerminationHandlerThatThrowsIsContainedAndTheNextOneRuns() {
        Monitor monitor = tickWith(new MonitorListener() { });
        AtomicInteger secondRan = new AtomicInteger();
        monitor.onTermination(r -> {
            throw new IllegalStateException("handler bug");
        });
        monitor.onTermination(r -> secondRan.incrementAndGet());
        monitor.startStepped().runUntil(ms(50));
        monitor.stop();

        assertEquals(1, secondRan.get(), "the second handler still ran");
        assertEquals(List.of("termination handler: handler bug"), handled);
        assertEquals(1, monitor.frameworkErrors());
    }

    @Test
    void theDefaultHandlerPrintsOneLinePerSecondAndFoldsTheRestIntoTheNextLine() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ManualClock wall = new ManualClock();
        RateLimitedErrorPrinter printer =
                new RateLimitedErrorPrinter(new PrintStream(bytes, true, StandardCharsets.UTF_8), wall);
        printer.onError("listener X.onCycle on task 'a'", new IllegalStateException("one"));
        printer.onError("listener X.onCycle on task 'a'", new IllegalStateException("two"));
        printer.onError("listener X.onCycle on task 'a'", new IllegalStateException("three"));
        wall.advance(ms(1000));
        printer.onError("listener X.onCycle on task 'a'", new IllegalStateException("four"));

        String[] lines = bytes.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals(2, lines.length, "one line, then one a second later");
        assertEquals("rtaware: framework error in listener X.onCycle on task 'a': java.lang.IllegalStateException: one",
                lines[0]);
        assertTrue(lines[1].endsWith("four (2 more faults since the previous line)"), lines[1]);
    }
}
