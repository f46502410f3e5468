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
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

class MinimalTimerSlackTest {

    /** A kernel that records the slack asked for and refuses it when told to. */
    private static final class SlackSched implements LinuxSched {
        final List<Long> asked = new CopyOnWriteArrayList<>();
        final int answer;

        SlackSched(int answer) {
            this.answer = answer;
        }

        @Override
        public int setFifo(int priority) {
            throw new AssertionError("a timer-slack setup never asks for SCHED_FIFO");
        }

        @Override
        public int scheduler() {
            return SCHED_OTHER;
        }

        @Override
        public int priority() {
            return 0;
        }

        @Override
        public int pinTo(int cpu) {
            throw new AssertionError("a timer-slack setup never pins");
        }

        @Override
        public int timerSlack(long slackNs) {
            asked.add(slackNs);
            return answer;
        }
    }

    @Test
    void everyTaskThreadAndWorkerAsksForOneNanosecond() {
        SlackSched sched = new SlackSched(0);
        MinimalTimerSlack setup = new MinimalTimerSlack(sched);
        setup.onTaskThreadStart(null, 0, 2);
        setup.onPoolWorkerStart(0, 1, 2);
        assertEquals(List.of(1L, 1L), sched.asked);
        assertEquals(0, setup.refused());
    }

    @Test
    void aRefusalIsCountedAndTheThreadRunsOn() {
        MinimalTimerSlack setup = new MinimalTimerSlack(new SlackSched(1));
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
