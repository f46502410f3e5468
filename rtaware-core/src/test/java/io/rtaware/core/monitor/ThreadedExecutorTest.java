package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.FnTask;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import io.rtaware.core.time.SystemClock;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Real threads: tolerant checks that the threaded executor works. Each rule is also tested
 * exactly on the manual clock; these tests only prove the wiring.
 */
@Tag("threads")
class ThreadedExecutorTest {

    private final Clock clock = new SystemClock();

    @Test
    void periodicTaskRunsRoughlyOncePerPeriod() throws InterruptedException {
        AtomicInteger runs = new AtomicInteger();
        AtomicBoolean rightThread = new AtomicBoolean(true);
        Monitor monitor = Monitor.builder(clock).task("tick", Schedule.periodic(Duration.ofMillis(10)), FnTask.of(now -> {
            runs.incrementAndGet();
            if (!Thread.currentThread().getName().equals("rtaware-tick")) {
                rightThread.set(false);
            }
        })).build();
        monitor.start();
        Thread.sleep(300);
        Report report = monitor.stop();

        int n = runs.get();
        assertTrue(n >= 15 && n <= 32, "about 30 runs of a 10 ms task in ~300 ms, got " + n);
        assertEquals(n, report.task("tick").runs(), "the report counts every run");
        assertEquals(report.task("tick").releases(), report.task("tick").runs() + report.task("tick").skipped(),
                "releases = runs + skipped");
        assertTrue(rightThread.get(), "the task runs on its own thread named rtaware-<task>");
    }

    @Test
    void aContinuousTaskThatKeepsThrowingIsPausedNotSpun() throws InterruptedException {
        Monitor monitor = Monitor.builder(clock).task("broken", Schedule.continuous(), FnTask.of(now -> {
            throw new IllegalStateException("connection lost");
        })).build();
        monitor.start();
        Thread.sleep(300);
        Report report = monitor.stop();

        long errors = report.task("broken").errors();
        // Without the pause this loop ran millions of cycles in a few seconds; with a 20 ms pause,
        // about 15 fit in 300 ms. The bound leaves room for a slow machine either way.
        assertTrue(errors >= 2 && errors <= 100, "a failing continuous task is paused after each error, got "
                + errors + " errors in ~300 ms");
        assertEquals(report.task("broken").runs(), errors, "every run failed and was counted");
    }

    @Test
    void stopAllFromATaskThreadTerminatesTheMonitor() throws InterruptedException {
        CountDownLatch handled = new CountDownLatch(1);
        Monitor monitor = Monitor.builder(clock)
                .task(new TaskSpec("bomb", Schedule.periodic(Duration.ofMillis(5)), ErrorPolicy.STOP_ALL, FnTask.of(now -> {
                    throw new IllegalStateException("boom");
                })))
                .task("bystander", Schedule.periodic(Duration.ofMillis(5)), FnTask.of(now -> { })).build();
        monitor.onTermination(r -> handled.countDown());
        monitor.start();

        assertTrue(monitor.awaitTermination(Duration.ofSeconds(10)), "STOP_ALL terminates the monitor");
        assertTrue(handled.await(10, TimeUnit.SECONDS), "the termination handler ran");
        assertEquals(1, monitor.report().task("bomb").errors(), "one error: the task was not released again");
    }

    @Test
    void stopIsIdempotentAndReturnsTheReport() throws InterruptedException {
        FnTask task = FnTask.of(now -> { });
        Monitor monitor = Monitor.builder(clock).task("t", Schedule.continuous(), task).build();
        monitor.start();
        Thread.sleep(20);
        Report first = monitor.stop();
        Report second = monitor.stop();
        assertSame(first, second, "stop() returns the same report every time");
        assertEquals(1, task.terminations, "terminate() once");
        assertTrue(first.task("t").runs() > 0, "the continuous task ran");
    }

    @Test
    void watchdogReportsAMissWhileTheTaskIsStillRunning() throws InterruptedException {
        CountDownLatch missReported = new CountDownLatch(1);
        AtomicBoolean sawItWhileRunning = new AtomicBoolean();
        AtomicBoolean stillRunningFlag = new AtomicBoolean();
        AtomicInteger cycle = new AtomicInteger();
        MonitorListener listener = new MonitorListener() {
            @Override
            public void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedNs, boolean stillRunning) {
                stillRunningFlag.set(stillRunning);
                missReported.countDown();
            }
        };
        Monitor monitor = Monitor.builder(clock).listener(listener)
                .task("stuck", Schedule.periodic(Duration.ofMillis(10)), FnTask.of(now -> {
                    if (cycle.getAndIncrement() == 0) {
                        // Stay in the cycle until the watchdog has reported the miss (or give up).
                        sawItWhileRunning.set(missReported.await(10, TimeUnit.SECONDS));
                    }
                })).build();
        monitor.start();
        assertTrue(missReported.await(10, TimeUnit.SECONDS), "a miss is reported");
        Report report = monitor.stop();

        assertTrue(sawItWhileRunning.get(), "the miss was reported while the cycle was still running");
        assertTrue(stillRunningFlag.get(), "reported with stillRunning = true");
        assertTrue(report.task("stuck").misses() >= 1, "counted in the report");
    }
}
