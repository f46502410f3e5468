package io.rtaware.rt;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.core.conditions.ThreadTimerSlack;
import io.rtaware.core.monitor.ExecutorKind;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.ThreadSetup;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.SystemClock;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.junit.jupiter.api.Test;

class MinimalTimerSlackTest {

    @Test
    void everyTaskThreadWorkerAndWatchdogAsksForOneNanosecond() {
        RecordingSched sched = new RecordingSched(1, 0);
        MinimalTimerSlack setup = new MinimalTimerSlack(sched);
        setup.onTaskThreadStart(null, 0, 2);
        setup.onPoolWorkerStart(0, 1, 2);
        setup.onWatchdogStart(2);
        assertEquals(List.of("slack 1", "slack 1", "slack 1"), sched.calls, "only the slack: no SCHED_FIFO, no pinning");
        assertEquals(0, setup.refused());
    }

    @Test
    void aRefusalIsCountedAndTheThreadRunsOn() {
        MinimalTimerSlack setup = new MinimalTimerSlack(new RecordingSched(0, 1));
        setup.onTaskThreadStart(null, 0, 1);
        assertEquals(1, setup.refused());
    }

    /** The kernel's default slack, as a thread of this JVM that nobody changed reads it. */
    private static OptionalLong defaultSlack() throws InterruptedException {
        ThreadTimerSlack probe = ThreadTimerSlack.ofThisMachine();
        Thread thread = new Thread(probe::observeCurrentThread);
        thread.start();
        thread.join();
        return probe.largestNs();
    }

    private static Monitor started(ExecutorKind kind, ThreadSetup setup) {
        Monitor.Builder builder = Monitor.builder(new SystemClock()).executor(kind).threadSetup(setup);
        for (int i = 0; i < 3; i++) {
            builder.task("t" + i, Schedule.periodic(Duration.ofMillis(50)), new Task() {
                @Override
                public void initialize(TaskSetup setup) {
                }

                @Override
                public void execute(long nowNs) {
                }
            });
        }
        Monitor monitor = builder.build();
        monitor.start();
        monitor.stop();
        return monitor;
    }

    /** On Linux, what each executor's threads really got, read back from /proc by the monitor. */
    @Test
    void theMonitorSeesOneNanosecondOnEveryThreadOfEitherExecutor() throws Exception {
        Optional<ThreadSetup> minimal = MinimalTimerSlack.load();
        OptionalLong kernel = defaultSlack();
        assumeTrue(minimal.isPresent() && kernel.isPresent(), "needs Linux, JNA and /proc/PID/timerslack_ns");
        assertNotEquals(1L, kernel.getAsLong(), "this JVM's threads start with a larger slack than 1 ns");

        for (ExecutorKind kind : List.of(ExecutorKind.threaded(), ExecutorKind.pooled(2,
                ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST))) {
            ThreadTimerSlack slack = started(kind, minimal.get()).timerSlack();
            assertEquals(OptionalLong.of(1), slack.largestNs(), kind + ": every thread has 1 ns");
            assertEquals(OptionalLong.of(1), slack.smallestNs(), kind.toString());

            ThreadTimerSlack without = started(kind, null).timerSlack();
            assertEquals(kernel, without.largestNs(), kind + ": without the setup, the kernel's slack");
        }
    }
}
