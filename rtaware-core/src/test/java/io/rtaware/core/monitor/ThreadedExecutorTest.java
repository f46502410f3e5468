package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.FnTask;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import io.rtaware.core.time.SystemClock;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The threaded and the pooled executor with their real threads, on a manual clock stepped by the
 * test (see {@link SteppedThreads}): the same exact counts as the step executor, because all
 * follow the one rulebook in {@link TaskRuntime}. Every rule test runs on both executors (the
 * pool with two workers); one test on the wall clock proves the real waiting.
 */
class ThreadedExecutorTest {

    /** The executors under test. */
    enum Kind {
        THREADED(ExecutorKind.threaded()),
        POOLED(ExecutorKind.pooled(2, ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST));

        final ExecutorKind executor;

        Kind(ExecutorKind executor) {
            this.executor = executor;
        }
    }

    private final ManualClock clock = new ManualClock();

    @Test
    void periodicTaskRunsOncePerPeriodOnItsOwnThread() {
        AtomicInteger runs = new AtomicInteger();
        AtomicBoolean rightThread = new AtomicBoolean(true);
        Monitor monitor = Monitor.builder(clock).task("tick", Schedule.periodic(Duration.ofMillis(10)), FnTask.of(now -> {
            runs.incrementAndGet();
            if (!Thread.currentThread().getName().equals("rtaware-tick")) {
                rightThread.set(false);
            }
        })).build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(300));
        Report report = monitor.stop();

        assertEquals(30, runs.get(), "releases at 0, 10, ..., 290 ms");
        assertEquals(30, report.task("tick").releases());
        assertEquals(30, report.task("tick").runs());
        assertEquals(0, report.task("tick").misses());
        assertEquals(0.0, report.task("tick").latenessUs().max(), "each release ran at its instant");
        assertTrue(rightThread.get(), "the task runs on its own thread named rtaware-<task>");
    }

    /**
     * With releases spread over the period, the watchdog sleeps until the earliest deadline that
     * could be missed (the next task's, a period after its release) and looks once per period; a
     * park that returns before its time (here: the manual clock's advance to every other task's
     * release; on a real clock a spurious wake-up) does not cost a scan of every task.
     */
    @Test
    void theWatchdogLooksOncePerPeriodWhenReleasesAreSpreadOverIt() {
        int tasks = 100;
        Monitor.Builder builder = Monitor.builder(clock);
        for (int i = 0; i < tasks; i++) {
            builder.task("t" + i, Schedule.periodic(Duration.ofMillis(10), Duration.ofNanos(i * ms(10) / tasks),
                    Duration.ofMillis(10)), FnTask.of(now -> { }));
        }
        Monitor monitor = builder.build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(500));
        Watchdog watchdog = ((ThreadedExecutor) monitor.executor()).watchdog();
        Report report = monitor.stop();

        assertEquals(tasks * 50, report.tasks().stream().mapToLong(t -> t.releases()).sum());
        assertEquals(50, watchdog.scans(), "once per 10 ms: not at each of the 100 releases of a"
                + " period, which each advance the manual clock (5000 scans before)");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void anOverrunSkipsToTheNextGridPointExactlyAsOnTheStepExecutor(Kind kind) {
        AtomicInteger cycle = new AtomicInteger();
        Monitor monitor = Monitor.builder(clock).executor(kind.executor).task("slow", Schedule.periodic(ms(10)), FnTask.of(now -> {
            if (cycle.getAndIncrement() == 2) {
                clock.advance(ms(25)); // release 2 at 20 ms ends at 45 ms: releases 3 and 4 are skipped
            }
        })).build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(100));
        Report report = monitor.stop();

        assertEquals(10, report.task("slow").releases(), "0..90 ms");
        assertEquals(8, report.task("slow").runs());
        assertEquals(2, report.task("slow").skipped());
        assertEquals(3, report.task("slow").misses(), "the late cycle plus two skipped releases");
        assertEquals(0.0, report.task("slow").latenessUs().max(), "the first run after the overrun, release 5 at"
                + " 50 ms, is on time: no catch-up of the skipped releases");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void aContinuousTaskThatKeepsThrowingIsPausedTwentyMillisecondsOfWorldTime(Kind kind) {
        Monitor monitor = Monitor.builder(clock).executor(kind.executor).task("broken", Schedule.continuous(), FnTask.of(now -> {
            throw new IllegalStateException("connection lost");
        })).build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(300));
        Report report = monitor.stop();

        assertEquals(15, report.task("broken").errors(), "one failing cycle every 20 ms: 0, 20, ..., 280 ms");
        assertEquals(15, report.task("broken").runs());
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void aContinuousTaskThatTakesNoTimeIsReleasedEveryIdleStep(Kind kind) {
        Monitor monitor = Monitor.builder(clock).executor(kind.executor).task("spin", Schedule.continuous(), FnTask.of(now -> { })).build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(50));
        Report report = monitor.stop();

        assertEquals(50, report.task("spin").runs(), "released every 1 ms idle step, as on the step executor");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void stopAllFromATaskThreadTerminatesTheMonitor(Kind kind) throws InterruptedException {
        CountDownLatch handled = new CountDownLatch(1);
        Monitor monitor = Monitor.builder(clock).executor(kind.executor)
                .task(new TaskSpec("bomb", Schedule.periodic(ms(5)), ErrorPolicy.STOP_ALL, FnTask.of(now -> {
                    throw new IllegalStateException("boom");
                })))
                .task("bystander", Schedule.periodic(ms(5)), FnTask.of(now -> { })).build();
        monitor.onTermination(r -> handled.countDown());
        monitor.start();

        assertTrue(monitor.awaitTermination(Duration.ofSeconds(10)), "STOP_ALL terminates the monitor");
        assertTrue(handled.await(10, TimeUnit.SECONDS), "the termination handler ran");
        assertEquals(1, monitor.report().task("bomb").errors(), "one error: the task was not released again");
        long bystanderRuns = monitor.report().task("bystander").runs();
        // The clock never moved, so release 0 at most; the stop may come before the bystander's
        // thread has run it (seen once in about ten runs of this test on the loaded machine).
        assertTrue(bystanderRuns <= 1, "the clock never moved: release 0 only, got " + bystanderRuns + " runs");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void stopIsIdempotentAndReturnsTheReport(Kind kind) {
        FnTask task = FnTask.of(now -> { });
        Monitor monitor = Monitor.builder(clock).executor(kind.executor).task("t", Schedule.continuous(), task).build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(3));
        Report first = monitor.stop();
        Report second = monitor.stop();
        assertSame(first, second, "stop() returns the same report every time");
        assertEquals(1, task.terminations, "terminate() once");
        assertEquals(3, first.task("t").runs(), "at 0, 1 and 2 ms");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void watchdogReportsAMissAtTheDeadlineWhileTheTaskIsStillRunning(Kind kind) throws InterruptedException {
        CountDownLatch missReported = new CountDownLatch(1);
        AtomicBoolean sawItWhileRunning = new AtomicBoolean();
        AtomicBoolean stillRunningFlag = new AtomicBoolean();
        long[] detectedNs = new long[1];
        AtomicInteger cycle = new AtomicInteger();
        MonitorListener listener = new MonitorListener() {
            @Override
            public void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedAt,
                                       boolean stillRunning) {
                stillRunningFlag.set(stillRunning);
                detectedNs[0] = detectedAt;
                missReported.countDown();
            }
        };
        Monitor monitor = Monitor.builder(clock).executor(kind.executor).listener(listener)
                .task("stuck", Schedule.periodic(ms(10)), FnTask.of(now -> {
                    if (cycle.getAndIncrement() == 0) {
                        clock.advance(ms(12));
                        // Stay in the cycle until the watchdog has reported the miss (or give up).
                        sawItWhileRunning.set(missReported.await(10, TimeUnit.SECONDS));
                    }
                })).build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(30));
        Report report = monitor.stop();

        assertTrue(sawItWhileRunning.get(), "the miss was reported while the cycle was still running");
        assertTrue(stillRunningFlag.get(), "reported with stillRunning = true");
        assertEquals(ms(12), detectedNs[0], "detected at the advance that passed the deadline");
        assertEquals(1, report.task("stuck").skipped(), "release 1 (10 ms) came due during the 12 ms cycle");
        assertEquals(2, report.task("stuck").misses(), "the late cycle counted once, plus the skipped release");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void onTheWallClockTheTaskThreadsReallyWait(Kind kind) throws InterruptedException {
        CountDownLatch threeRuns = new CountDownLatch(3);
        Monitor monitor = Monitor.builder(new SystemClock()).executor(kind.executor)
                .task("tick", Schedule.periodic(ms(10)), FnTask.of(now -> threeRuns.countDown())).build();
        monitor.start();
        assertTrue(threeRuns.await(10, TimeUnit.SECONDS), "three cycles ran");
        Report report = monitor.stop();

        assertTrue(report.task("tick").runs() >= 3);
        assertEquals(report.task("tick").releases(), report.task("tick").runs() + report.task("tick").skipped(),
                "releases = runs + skipped");
    }

    /**
     * The builder's thread setup reaches the executor's watchdog, once, on the watchdog's own
     * thread (where {@code --realtime} raises it above the tasks), with the monitor's task count.
     */
    @ParameterizedTest
    @EnumSource(Kind.class)
    void theThreadSetupRunsOnTheWatchdogOnce(Kind kind) throws InterruptedException {
        java.util.List<String> watchdogs = new java.util.concurrent.CopyOnWriteArrayList<>();
        ThreadSetup setup = new ThreadSetup() {
            @Override
            public void onTaskThreadStart(TaskInfo task, int rmRank, int taskCount) {
            }

            @Override
            public void onPoolWorkerStart(int worker, int rmRank, int taskCount) {
            }

            @Override
            public void onWatchdogStart(int taskCount) {
                watchdogs.add(Thread.currentThread().getName() + " " + taskCount);
            }
        };
        CountDownLatch oneRun = new CountDownLatch(1);
        Monitor monitor = Monitor.builder(new SystemClock()).executor(kind.executor).threadSetup(setup)
                .task("a", Schedule.periodic(ms(10)), FnTask.of(now -> oneRun.countDown()))
                .task("b", Schedule.periodic(ms(20)), FnTask.of(now -> { })).build();
        monitor.start();
        assertTrue(oneRun.await(10, TimeUnit.SECONDS), "a cycle ran");
        monitor.stop(); // joins the watchdog, which runs the setup before anything else
        assertEquals(java.util.List.of(io.rtaware.core.agent.ThreadNames.WATCHDOG + " 2"), watchdogs);
    }

    @Test
    void withASleeperTheTaskThreadsSleepWithItAndNothingElseDoes() throws InterruptedException {
        java.util.Set<String> sleepers = java.util.concurrent.ConcurrentHashMap.newKeySet();
        AtomicInteger sleeps = new AtomicInteger();
        CountDownLatch threeRuns = new CountDownLatch(3);
        Monitor monitor = Monitor.builder(new SystemClock())
                .sleeper(nanoTime -> {
                    sleeps.incrementAndGet();
                    sleepers.add(Thread.currentThread().getName());
                    java.util.concurrent.locks.LockSupport.parkNanos(nanoTime - System.nanoTime());
                })
                .task("tick", Schedule.periodic(ms(10)), FnTask.of(now -> threeRuns.countDown())).build();
        monitor.start();
        assertTrue(threeRuns.await(10, TimeUnit.SECONDS), "three cycles ran");
        Report report = monitor.stop();

        assertTrue(sleeps.get() >= 2, "the task thread slept with the sleeper between its cycles: " + sleeps);
        assertEquals(java.util.Set.of("rtaware-tick"), sleepers, "the watchdog still parks (a task wakes it)");
        assertEquals(report.task("tick").releases(), report.task("tick").runs() + report.task("tick").skipped());
    }
}
