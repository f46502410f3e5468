package io.rtaware.rt;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.core.monitor.ExecutorKind;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.monitor.ThreadSetup;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.testing.FixedTaskInfo;
import io.rtaware.core.testing.Waits;
import io.rtaware.core.time.SystemClock;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

class RealtimeThreadsTest {

    private static final TaskInfo TASK = new FixedTaskInfo("a", 0, Schedule.periodic(Duration.ofMillis(10)), List.of());

    @Test
    void whenFifoIsDeniedOneLineSaysSoAndThreadsStayNormal() {
        RecordingSched sched = new RecordingSched(1, 0); // SCHED_FIFO refused with EPERM
        ByteArrayOutputStream buffer = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(buffer, true, StandardCharsets.UTF_8);
        RealtimeThreads rt = RealtimeThreads.configure(sched, 80, Map.of("a", 1), err);
        rt.onTaskThreadStart(TASK, 0, 2);
        rt.onTaskThreadStart(TASK, 1, 2);

        assertFalse(rt.fifo());
        String printed = buffer.toString(StandardCharsets.UTF_8);
        assertEquals(1, printed.lines().count(), printed);
        assertTrue(printed.contains("SCHED_FIFO not permitted (EPERM"), printed);
        assertTrue(printed.contains("running with normal threads"), printed);
        // Only the probe asked for FIFO; every thread still got 1 ns slack and its CPU.
        assertEquals(List.of("fifo 1", "slack 1", "pin 1", "slack 1", "pin 1"), sched.calls);
        assertEquals(0, rt.fifoThreads());
    }

    @Test
    void poolWorkersGetTheFastestPooledTasksPriorityAndNoPin() {
        RecordingSched sched = new RecordingSched(1, 0); // SCHED_FIFO refused with EPERM
        RealtimeThreads rt = RealtimeThreads.configure(sched, 80, Map.of("a", 1),
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        sched.calls.clear();
        rt.onPoolWorkerStart(0, 2, 5);
        // FIFO is denied here, so only the slack is set; a pool worker is never pinned.
        assertEquals(List.of("slack 1"), sched.calls, "a denied pool worker only gets timer slack");
    }

    @Test
    void prioritiesAreRateMonotonicFromTheTop() {
        RealtimeThreads rt = RealtimeThreads.configure(new RecordingSched(1, 0), 80, Map.of(),
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        assertEquals(80, rt.priorityOf(0));
        assertEquals(79, rt.priorityOf(1));
        assertEquals(1, rt.priorityOf(200));
        assertEquals(81, rt.watchdogPriority(), "the watchdog above every task");
        RealtimeThreads top = RealtimeThreads.configure(new RecordingSched(1, 0), 99, Map.of(),
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        assertEquals(99, top.watchdogPriority(), "at most 99");
    }

    @Test
    void theWatchdogGetsOneAboveTheTopPriorityAndNoSlack() {
        RecordingSched sched = new RecordingSched(0, 0); // SCHED_FIFO permitted
        ByteArrayOutputStream buffer = new ByteArrayOutputStream();
        RealtimeThreads rt = RealtimeThreads.configure(sched, 80, Map.of(),
                new PrintStream(buffer, true, StandardCharsets.UTF_8));
        sched.calls.clear();
        rt.onWatchdogStart(3);
        assertEquals(List.of("slack 1", "fifo 81"), sched.calls);
        assertEquals(1, rt.fifoThreads());
        assertEquals("", buffer.toString(StandardCharsets.UTF_8));
    }

    /** Where the machine permits it (root here), task threads really are SCHED_FIFO. */
    @Test
    void taskThreadsRunAsSchedFifoWherePermitted() throws Exception {
        LinuxSched sched;
        try {
            sched = JnaLinuxSched.load();
        } catch (UnsupportedOperationException e) {
            assumeTrue(false, "no native access: " + e.getMessage());
            return;
        }
        ByteArrayOutputStream buffer = new ByteArrayOutputStream();
        RealtimeThreads rt = RealtimeThreads.configure(sched, 80, Map.of(),
                new PrintStream(buffer, true, StandardCharsets.UTF_8));
        assumeTrue(rt.fifo(), "SCHED_FIFO not permitted here: " + buffer);

        List<Integer> policies = new CopyOnWriteArrayList<>();
        LinuxSched probe = sched;
        Task task = new Task() {
            @Override
            public void initialize(TaskSetup setup) {
            }

            @Override
            public void execute(long nowNs) {
                if (policies.isEmpty()) {
                    policies.add(probe.scheduler());
                }
            }
        };
        Monitor monitor = Monitor.builder(new SystemClock()).threadSetup(rt)
                .task("rt", Schedule.periodic(Duration.ofMillis(5)), task).build();
        monitor.start();
        Waits.until(() -> !policies.isEmpty(), Duration.ofSeconds(10), "a cycle of the task");
        monitor.stop();
        assertEquals(List.of(LinuxSched.SCHED_FIFO), policies);
        assertEquals(2, rt.fifoThreads(), "the task's thread and the watchdog");
        assertEquals("", buffer.toString(StandardCharsets.UTF_8));
        // The test thread itself was never touched.
        assertEquals(LinuxSched.SCHED_OTHER, sched.scheduler());
    }

    /**
     * Where the machine permits it (root here): with the pooled executor, the workers that run the
     * periodic tasks are SCHED_FIFO at the priority of the fastest task (rank 0: the top priority).
     * Before the pool's thread factory ran the thread setup, they stayed SCHED_OTHER.
     */
    @Test
    void pooledWorkersRunAsSchedFifoAtTheTopPriorityWherePermitted() throws Exception {
        LinuxSched sched;
        try {
            sched = JnaLinuxSched.load();
        } catch (UnsupportedOperationException e) {
            assumeTrue(false, "no native access: " + e.getMessage());
            return;
        }
        ByteArrayOutputStream buffer = new ByteArrayOutputStream();
        RealtimeThreads rt = RealtimeThreads.configure(sched, 70, Map.of(),
                new PrintStream(buffer, true, StandardCharsets.UTF_8));
        assumeTrue(rt.fifo(), "SCHED_FIFO not permitted here: " + buffer);

        Set<String> seen = Collections.synchronizedSet(new TreeSet<>());
        LinuxSched probe = sched;
        List<String> watchdog = new CopyOnWriteArrayList<>();
        ThreadSetup observed = new ThreadSetup() {
            @Override
            public void onTaskThreadStart(TaskInfo task, int rmRank, int taskCount) {
                rt.onTaskThreadStart(task, rmRank, taskCount);
            }

            @Override
            public void onPoolWorkerStart(int worker, int rmRank, int taskCount) {
                rt.onPoolWorkerStart(worker, rmRank, taskCount);
            }

            @Override
            public void onWatchdogStart(int taskCount) {
                rt.onWatchdogStart(taskCount);
                watchdog.add(Thread.currentThread().getName() + " policy " + probe.scheduler()
                        + " priority " + probe.priority());
            }
        };
        Monitor.Builder builder = Monitor.builder(new SystemClock()).threadSetup(observed)
                .executor(ExecutorKind.pooled(2, ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST));
        for (int i = 0; i < 4; i++) {
            builder.task("t" + i, Schedule.periodic(Duration.ofMillis(2 + i)), new Task() {
                @Override
                public void initialize(TaskSetup setup) {
                }

                @Override
                public void execute(long nowNs) {
                    seen.add(Thread.currentThread().getName() + " policy " + probe.scheduler()
                            + " priority " + probe.priority());
                }
            });
        }
        Monitor monitor = builder.build();
        monitor.start();
        Waits.until(() -> !seen.isEmpty(), Duration.ofSeconds(10), "a cycle of a pooled task");
        monitor.stop(); // every worker ran its thread setup before start returned
        assertFalse(seen.isEmpty(), "the pooled tasks ran");
        for (String thread : seen) {
            assertTrue(thread.matches("rtaware-pool-[01] policy 1 priority 70"),
                    "a cycle ran on a worker that is SCHED_FIFO (1) at the top priority: " + seen);
        }
        assertEquals(List.of(ThreadNames.WATCHDOG + " policy 1 priority 71"), watchdog,
                "the pool's watchdog is SCHED_FIFO one above the workers");
        assertEquals(3, rt.fifoThreads(), "both workers and the watchdog, no task thread");
        assertEquals("", buffer.toString(StandardCharsets.UTF_8));
    }
}
