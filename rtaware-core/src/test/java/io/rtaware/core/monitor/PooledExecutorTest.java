package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.FnTask;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;

/**
 * What only the pooled executor does: the order in which a free worker takes due releases, the
 * lateness of a release that waits for a worker, and the tasks that keep a thread of their own.
 * Real threads on a manual clock stepped by the test ({@link SteppedThreads}), exact counts.
 */
class PooledExecutorTest {

    private final ManualClock clock = new ManualClock();
    private final List<String> starts = new CopyOnWriteArrayList<>();

    private FnTask recording(String name) {
        return FnTask.of(now -> starts.add(name + "@" + now / 1_000_000));
    }

    private static Schedule periodic(long periodMs, long deadlineMs) {
        return Schedule.periodic(Duration.ofMillis(periodMs), Duration.ZERO, Duration.ofMillis(deadlineMs));
    }

    private Report run(ExecutorKind.PoolOrder order, int workers, long untilMs, Monitor.Builder builder) {
        Monitor monitor = builder.executor(ExecutorKind.pooled(workers, order)).build();
        monitor.start();
        new SteppedThreads(monitor, clock).runUntil(ms(untilMs));
        return monitor.stop();
    }

    @Test
    void oneWorkerRunsTheDueReleaseWithTheEarliestDeadlineFirst() {
        Monitor.Builder builder = Monitor.builder(clock)
                .task("slow", periodic(20, 20), recording("slow"))
                .task("urgent", periodic(20, 5), recording("urgent"));
        run(ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST, 1, 30, builder);

        assertEquals(List.of("urgent@0", "slow@0", "urgent@20", "slow@20"), starts,
                "both due at 0 and 20 ms: the 5 ms deadline first, although registered second");
    }

    @Test
    void rateMonotonicRunsTheShorterPeriodFirstWhateverTheDeadline() {
        Monitor.Builder builder = Monitor.builder(clock)
                .task("tightButRare", periodic(20, 4), recording("rare"))
                .task("frequent", periodic(10, 10), recording("frequent"));
        run(ExecutorKind.PoolOrder.RATE_MONOTONIC, 1, 15, builder);

        assertEquals(List.of("frequent@0", "rare@0", "frequent@10"), starts,
                "rate-monotonic: the 10 ms task first at 0 ms, although the 20 ms task's deadline is earlier");
    }

    @Test
    void withOneDeadlineForAllTasksDueReleasesRunInReleaseOrderWhichIsDeadlineOrder() {
        // Every task has a 5 ms deadline, so the worker takes due releases straight from the
        // waiting heap. 'hog' holds the only worker from 0 to 3 ms; 'b' (released at 2 ms,
        // deadline 7) and 'a' (released at 1 ms, deadline 6) are then both due: 'a' first,
        // although 'b' was registered first.
        Monitor.Builder builder = Monitor.builder(clock)
                .task("hog", periodic(10, 5), FnTask.of(now -> {
                    if (now == 0) {
                        clock.advance(ms(3));
                    }
                }))
                .task("b", Schedule.periodic(Duration.ofMillis(10), Duration.ofMillis(2), Duration.ofMillis(5)),
                        recording("b"))
                .task("a", Schedule.periodic(Duration.ofMillis(10), Duration.ofMillis(1), Duration.ofMillis(5)),
                        recording("a"));
        Report report = run(ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST, 1, 9, builder);

        assertEquals(List.of("a@3", "b@3"), starts, "earliest deadline first among the due releases");
        assertEquals(0, report.task("a").misses() + report.task("b").misses(), "both start before their deadlines");
        assertEquals(2000.0, report.task("a").latenessUs().max(), "'a' waited 2 ms for the worker");
    }

    @Test
    void aReleaseWaitingForTheOnlyWorkerIsLateByTheCycleBeforeIt() {
        Monitor.Builder builder = Monitor.builder(clock)
                .task("busy", periodic(10, 10), FnTask.of(now -> clock.advance(ms(3))))
                .task("waits", periodic(10, 10), recording("waits"));
        Report report = run(ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST, 1, 20, builder);

        assertEquals(List.of("waits@3", "waits@13"), starts, "each release of 'waits' starts when 'busy' returns");
        assertEquals(3000.0, report.task("waits").latenessUs().max(), "lateness = start - release = 3 ms");
        assertEquals(0, report.task("waits").misses(), "3 ms late, done long before its 10 ms deadline");
    }

    @Test
    void twoWorkersRunTwoHundredTasksOnTheirGridWithoutAMiss() {
        Monitor.Builder builder = Monitor.builder(clock);
        for (int i = 0; i < 200; i++) {
            builder.task("t" + i, Schedule.periodic(ms(10)), FnTask.of(now -> { }));
        }
        Report report = run(ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST, 2, 100, builder);

        for (int i = 0; i < 200; i++) {
            assertEquals(10, report.task("t" + i).runs(), "t" + i + ": releases at 0, 10, ..., 90 ms");
            assertEquals(0, report.task("t" + i).misses(), "t" + i);
            assertEquals(0.0, report.task("t" + i).latenessUs().max(), "t" + i + ": zero-time cycles are never late");
        }
    }

    @Test
    void aWorkerWithNothingDueTakesTheDueReleasesOfABusyWorkersShard() {
        // Three tasks on two workers: slots 0 and 1 are worker 0's shard, slot 2 worker 1's.
        // 'busy' (slot 0, released at 0 ms) moves the clock to 2 ms, then holds its worker until
        // 'stolen' (slot 1, released at 1 ms) has run. Without stealing, both would wait for the
        // one worker of their shard. With it, whichever worker comes second to shard 0 takes what
        // the other cannot: worker 1 ('idle' is all its shard has due, at 0 ms) takes 'stolen' at
        // 2 ms, or, if it reached shard 0 at 0 ms first, 'busy', and worker 0 then runs 'stolen'.
        CountDownLatch stolenRan = new CountDownLatch(1);
        AtomicBoolean ranWhileBusy = new AtomicBoolean();
        List<String> busyOn = new CopyOnWriteArrayList<>();
        List<String> stolenOn = new CopyOnWriteArrayList<>();
        Monitor.Builder builder = Monitor.builder(clock)
                .task("busy", periodic(10, 10), FnTask.of(now -> {
                    if (now == 0) {
                        busyOn.add(Thread.currentThread().getName());
                        clock.advance(ms(2));
                        ranWhileBusy.set(awaitUninterruptibly(stolenRan));
                    }
                }))
                .task("stolen", Schedule.periodic(Duration.ofMillis(10), Duration.ofMillis(1), Duration.ofMillis(10)),
                        FnTask.of(now -> {
                            stolenOn.add(Thread.currentThread().getName() + "@" + now / 1_000_000);
                            stolenRan.countDown();
                        }))
                .task("idle", periodic(10, 10), FnTask.of(now -> { }));
        Report report = run(ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST, 2, 5, builder);

        assertTrue(ranWhileBusy.get(), "'stolen' ran while 'busy' held its worker, not after");
        assertEquals(1, busyOn.size());
        assertEquals(1, stolenOn.size(), stolenOn.toString());
        assertTrue(stolenOn.get(0).endsWith("@2"), "when the clock reached 2 ms: " + stolenOn);
        assertFalse(stolenOn.get(0).startsWith(busyOn.get(0) + "@"), "on the other worker: " + busyOn + " " + stolenOn);
        assertEquals(1000.0, report.task("stolen").latenessUs().max(), "released at 1 ms, started at 2 ms");
        assertEquals(0, report.task("stolen").misses());
    }

    @Test
    void aPoolWhosePreparationTookMillisecondsStartsThatFarAheadTwiceAndAQuickOneNow() {
        assertEquals(ms(100), PooledExecutor.startInstantNs(ms(100), 0), "on a manual clock preparing takes no time");
        assertEquals(ms(100), PooledExecutor.startInstantNs(ms(100), PooledExecutor.START_AHEAD_ABOVE_NS),
                "up to half a millisecond: now");
        assertEquals(ms(100) + ms(20), PooledExecutor.startInstantNs(ms(100), ms(10)),
                "10 000 tasks prepared in 10 ms start 20 ms ahead, so each is started before its first release");
    }

    /** @return whether the latch opened (a guard against a hang, not a timing: it opens at once when the pool works) */
    private static boolean awaitUninterruptibly(CountDownLatch latch) {
        try {
            return latch.await(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    @Test
    void aTaskThatBlocksKeepsAThreadOfItsOwnAndPeriodicTasksRunOnTheWorkers() {
        List<String> threads = new CopyOnWriteArrayList<>();
        Task blocking = new Task() {
            @Override
            public void initialize(TaskSetup setup) {
            }

            @Override
            public void execute(long nowNs) {
                threads.add("io:" + Thread.currentThread().getName());
            }

            @Override
            public boolean blocks() {
                return true;
            }
        };
        Monitor.Builder builder = Monitor.builder(clock)
                .task("io", Schedule.periodic(ms(10)), blocking)
                .task("loop", Schedule.continuous(), FnTask.of(now -> threads.add("loop:" + Thread.currentThread().getName())))
                .task("calc", Schedule.periodic(ms(10)), FnTask.of(now -> threads.add("calc:" + Thread.currentThread().getName())));
        Report report = run(ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST, 1, 5, builder);

        assertTrue(threads.contains("io:rtaware-io"), "a blocking periodic task runs on its own thread: " + threads);
        assertTrue(threads.contains("loop:rtaware-loop"), "a continuous task runs on its own thread: " + threads);
        assertTrue(threads.contains("calc:rtaware-pool-0"), "a periodic task runs on a pool worker: " + threads);
        assertEquals(5, report.task("loop").runs(), "the continuous task at 0..4 ms, one idle step apart");
        assertEquals(1, report.task("io").runs());
    }
}
