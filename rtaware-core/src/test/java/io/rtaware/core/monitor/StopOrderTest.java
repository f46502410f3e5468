package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.report.Report;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The order of a stop: the tasks that {@link Task#stopsFirst() stop first} (those that command
 * the robot) are terminated while the others may still be in their last cycle; and a stop that
 * reaches the monitor again from inside the termination, or from a cycle while another thread
 * terminates, does not wait for itself. Real threads on a manual clock, ordered by latches.
 */
class StopOrderTest {

    private final ManualClock clock = new ManualClock();
    private final List<String> terminated = new CopyOnWriteArrayList<>();

    /**
     * A task made of a cycle and a termination, which it logs; its components answer
     * {@link Task#stopsFirst()} and {@link Task#blocks()}.
     */
    private record Probe(List<String> log, String name, boolean stopsFirst, boolean blocks, Cycle cycle,
                         Runnable onTerminate) implements Task {
        @Override
        public void initialize(TaskSetup setup) {
        }

        @Override
        public void execute(long nowNs) throws Exception {
            cycle.run();
        }

        @Override
        public void terminate() {
            log.add(name);
            onTerminate.run();
        }
    }

    /** A cycle's body. */
    @FunctionalInterface
    private interface Cycle {
        void run() throws Exception;
    }

    private Probe probe(String name, boolean first) {
        return new Probe(terminated, name, first, false, () -> { }, () -> { });
    }

    @Test
    void theTasksThatStopFirstAreTerminatedFirstEachGroupInRegistrationOrder() {
        Monitor monitor = Monitor.builder(clock)
                .task("a", Schedule.periodic(ms(10)), probe("a", false))
                .task("driver", Schedule.periodic(ms(10)), probe("driver", true))
                .task("c", Schedule.periodic(ms(10)), probe("c", false))
                .task("arm", Schedule.periodic(ms(10)), probe("arm", true)).build();
        monitor.startStepped().runUntil(ms(100));

        monitor.stop();

        assertEquals(List.of("driver", "arm", "a", "c"), terminated, "stop-first tasks, then the rest");
    }

    /**
     * A planner in the middle of its cycle holds up no stop of the robot: the driver is
     * terminated while the planner's cycle still runs. (Were the planner waited for first, the
     * stop would interrupt it after five seconds and its wait would end without the driver's stop.)
     */
    @Test
    void theRobotStopsWhileAnotherTaskIsStillInItsCycleOnTheThreadedExecutor() throws InterruptedException {
        theRobotStopsWhileAnotherTaskIsStillInItsCycle(Monitor.builder(clock), false);
    }

    /** Under the pool the driver has a thread of its own (it blocks on its link), the planner is pooled. */
    @Test
    void theRobotStopsWhileAnotherTaskIsStillInItsCycleOnThePooledExecutor() throws InterruptedException {
        theRobotStopsWhileAnotherTaskIsStillInItsCycle(
                Monitor.builder(clock).executor(ExecutorKind.pooled(1, ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST)),
                true);
    }

    private void theRobotStopsWhileAnotherTaskIsStillInItsCycle(Monitor.Builder builder, boolean driverBlocks)
            throws InterruptedException {
        CountDownLatch plannerInCycle = new CountDownLatch(1);
        CountDownLatch driverStopped = new CountDownLatch(1);
        AtomicReference<String> planner = new AtomicReference<>("planner's cycle never ended");
        Monitor monitor = builder
                .task("planner", Schedule.periodic(ms(100)), new Probe(terminated, "planner", false, false, () -> {
                    plannerInCycle.countDown();
                    try {
                        driverStopped.await();
                        planner.set("driver stopped during the planner's cycle");
                    } catch (InterruptedException e) {
                        planner.set("planner's cycle interrupted before the driver stopped");
                    }
                }, () -> { }))
                .task("driver", Schedule.periodic(ms(10)),
                        new Probe(terminated, "driver", true, driverBlocks, () -> { }, driverStopped::countDown))
                .build();
        monitor.start();
        plannerInCycle.await();

        monitor.stop();

        assertEquals("driver stopped during the planner's cycle", planner.get(), "the planner's cycle");
        assertEquals(List.of("driver", "planner"), terminated, "the driver terminated first");
    }

    /** A deadlock guard, not a measure: without the fix the handler waits for its own stop forever. */
    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aStopFromInsideTheTerminationReturnsAtOnce() {
        AtomicReference<Monitor> self = new AtomicReference<>();
        AtomicReference<Report> fromTerminate = new AtomicReference<>();
        AtomicReference<Report> fromHandler = new AtomicReference<>();
        Monitor monitor = Monitor.builder(clock).task("t", Schedule.periodic(ms(10)),
                new Probe(terminated, "t", false, false, () -> { }, () -> fromTerminate.set(self.get().stop()))).build();
        self.set(monitor);
        monitor.onTermination(report -> fromHandler.set(monitor.stop()));
        monitor.startStepped().runUntil(ms(50));

        Report report = monitor.stop();

        assertNull(fromTerminate.get(), "from terminate(): no report yet");
        assertSame(report, fromHandler.get(), "from a termination handler: the report it is handed");
    }

    /**
     * A task whose cycle stops the monitor while another thread is terminating it gets an answer
     * at once: the termination is waiting for that very cycle. (Were it to wait for the end, the
     * terminating thread would give up on it after ten seconds and the report would be built by
     * then.)
     */
    @Test
    void aStopFromACycleWhileAnotherThreadTerminatesDoesNotWaitForItself() throws InterruptedException {
        CountDownLatch inCycle = new CountDownLatch(1);
        CountDownLatch terminationBegun = new CountDownLatch(1);
        AtomicReference<Monitor> self = new AtomicReference<>();
        AtomicReference<Report> fromCycle = new AtomicReference<>();
        AtomicReference<String> cycleEnd = new AtomicReference<>("the cycle never ended");
        Monitor monitor = Monitor.builder(clock)
                .task("finisher", Schedule.periodic(ms(100)), new Probe(terminated, "finisher", false, false, () -> {
                    inCycle.countDown();
                    terminationBegun.await();
                    fromCycle.set(self.get().stop());
                    cycleEnd.set("the cycle's stop() returned");
                }, () -> { }))
                // terminated first, so its termination says that the other thread's stop has begun
                .task("witness", Schedule.periodic(ms(10)),
                        new Probe(terminated, "witness", true, false, () -> { }, terminationBegun::countDown))
                .build();
        self.set(monitor);
        monitor.start();
        inCycle.await();

        Report report = monitor.stop();

        assertEquals("the cycle's stop() returned", cycleEnd.get(), "the cycle returned before the report was built");
        assertNull(fromCycle.get(), "the cycle's stop() answered before the report existed");
        assertNotNull(report, "the terminating thread built the report");
        assertTrue(terminated.containsAll(List.of("witness", "finisher")), "both terminated: " + terminated);
    }
}
