package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.FnTask;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/**
 * {@link Monitor#runUntilStopped(PrintStream)}: every way a run ends (Ctrl-C through the
 * shutdown hook, a stop from another thread, from a task's cycle, an interrupt), each with the
 * summary printed once and the hook gone unless the JVM is exiting. Real task threads on a
 * manual clock, ordered by latches; Ctrl-C is the hook run as the JVM runs it (a thread started
 * and waited for). The real JVM and SIGINT: {@code ReadmeExampleTest}.
 */
class RunUntilStoppedTest {

    private static final String SUMMARY = "rtaware summary:";

    private final ManualClock clock = new ManualClock();
    private final CountDownLatch firstCycle = new CountDownLatch(1);
    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private final PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
    private final FakeHooks hooks = new FakeHooks();

    /** The JVM's hooks as a test holds them: Ctrl-C runs the hook and waits for it, then removal fails. */
    private static final class FakeHooks implements ShutdownHooks {
        final List<Thread> added = new ArrayList<>();
        final List<Thread> removed = new ArrayList<>();
        volatile boolean shuttingDown;
        /** Ctrl-C as soon as the hook is installed, before the start. */
        boolean ctrlCOnAdd;

        @Override
        public synchronized void add(Thread hook) {
            added.add(hook);
            if (ctrlCOnAdd) {
                ctrlC();
            }
        }

        @Override
        public synchronized void remove(Thread hook) {
            if (shuttingDown) {
                throw new IllegalStateException("Shutdown in progress");
            }
            removed.add(hook);
        }

        /** What the JVM does on SIGINT: runs every hook on its own thread and waits for them. */
        void ctrlC() {
            shuttingDown = true;
            for (Thread hook : added) {
                hook.start();
                try {
                    hook.join();
                } catch (InterruptedException e) {
                    throw new AssertionError(e);
                }
            }
        }
    }

    private Monitor oneTask(FnTask.Body body) {
        return Monitor.builder(clock).task("t", Schedule.periodic(ms(10)), FnTask.of(now -> {
            body.execute(now);
            firstCycle.countDown();
        })).build();
    }

    private String printed() {
        return bytes.toString(StandardCharsets.UTF_8);
    }

    private static int occurrences(String text, String part) {
        int count = 0;
        for (int at = text.indexOf(part); at >= 0; at = text.indexOf(part, at + 1)) {
            count++;
        }
        return count;
    }

    /**
     * A monitor of one task whose {@code runUntilStopped} runs on a thread of its own, as on a
     * program's main thread; built once the task's first cycle has run.
     */
    private final class MainThread {
        final Monitor monitor = oneTask(now -> { });
        final AtomicReference<Report> returned = new AtomicReference<>();
        final AtomicReference<Boolean> interrupted = new AtomicReference<>();
        final Thread thread = new Thread(() -> {
            returned.set(monitor.runUntilStopped(out, hooks));
            interrupted.set(Thread.currentThread().isInterrupted());
        }, "test-main");

        MainThread() throws InterruptedException {
            thread.start();
            firstCycle.await();
        }
    }

    @Test
    void ctrlCStopsTheRunAndTheHookReturnsOnlyOnceTheSummaryIsPrinted() throws InterruptedException {
        MainThread main = new MainThread();

        hooks.ctrlC();
        // The JVM exits once its hooks have returned: the summary must be out by then.
        String atExit = printed();
        assertTrue(atExit.startsWith("rtaware: running 1 task; Ctrl-C stops them and prints the summary\n"),
                "the line at the start: " + atExit);
        assertEquals(1, occurrences(atExit, SUMMARY), "the summary, once, before the hook returned: " + atExit);
        assertTrue(atExit.contains("\nt "), "the summary has the task's row: " + atExit);

        main.thread.join();
        assertSame(main.monitor.report(), main.returned.get(), "runUntilStopped returns the report");
        assertEquals(1, main.returned.get().task("t").runs(), "the task ran its release at 0 ms");
        assertEquals(List.of(), hooks.removed, "the hook is not removed while the JVM shuts down (it cannot be)");
    }

    @Test
    void aStopInATasksCycleEndsTheRunAndRemovesTheHook() {
        AtomicReference<Monitor> self = new AtomicReference<>();
        Monitor monitor = oneTask(now -> self.get().stop());
        self.set(monitor);

        Report report = monitor.runUntilStopped(out, hooks);

        assertEquals(1, report.task("t").runs(), "the cycle that stopped the run ran");
        assertEquals(1, occurrences(printed(), SUMMARY), "the summary, once");
        assertEquals(hooks.added, hooks.removed, "the hook is removed: the run ended without the JVM exiting");
        assertEquals(1, hooks.added.size(), "one hook");
    }

    @Test
    void aStopFromAnotherThreadEndsTheRun() throws InterruptedException {
        MainThread main = new MainThread();

        Report report = main.monitor.stop();
        main.thread.join();

        assertSame(report, main.returned.get(), "runUntilStopped returns the report stop() built");
        assertEquals(1, occurrences(printed(), SUMMARY), "the summary, once");
        assertEquals(hooks.added, hooks.removed, "the hook is removed");
    }

    @Test
    void anInterruptOfTheWaitingThreadStopsTheRunAndStaysSet() throws InterruptedException {
        MainThread main = new MainThread();

        main.thread.interrupt();
        main.thread.join();

        assertNotNull(main.returned.get(), "the run was stopped and its report returned");
        assertTrue(main.monitor.isTerminated(), "the monitor terminated");
        assertEquals(Boolean.TRUE, main.interrupted.get(), "the interrupt stays set for the caller");
        assertEquals(1, occurrences(printed(), SUMMARY), "the summary, once");
        assertEquals(hooks.added, hooks.removed, "the hook is removed");
    }

    @Test
    void ctrlCBeforeTheStartStillEndsWithTheSummary() {
        Monitor monitor = oneTask(now -> { });
        hooks.ctrlCOnAdd = true;

        Report report = monitor.runUntilStopped(out, hooks);

        assertEquals(0, report.task("t").runs(), "nothing ran");
        assertEquals(1, occurrences(printed(), SUMMARY), "the hook printed the summary: " + printed());
        assertTrue(!printed().contains("rtaware: running"), "no line says the tasks run: " + printed());
    }

    @Test
    void aMonitorThatHasStartedIsRefusedAndNoHookIsLeft() {
        Monitor monitor = oneTask(now -> { });
        monitor.startStepped();

        IllegalStateException e = assertThrows(IllegalStateException.class, () -> monitor.runUntilStopped(out, hooks));

        assertEquals("runUntilStopped needs a monitor that has not started", e.getMessage(), "the message");
        assertEquals(List.of(), hooks.added, "no hook was installed");
        monitor.stop();
        assertEquals(0, occurrences(printed(), SUMMARY), "the refused call printed nothing");
    }
}
