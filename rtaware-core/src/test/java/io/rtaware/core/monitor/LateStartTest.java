package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.FnTask;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A cycle that can only start after its deadline (it waited for a worker, or its thread woke
 * late) has missed before it runs: the miss is reported at its start, once, and the watchdog is
 * not needed for it. On the step executor: a task whose deadline is shorter than the cycle
 * before it on the same instant.
 */
class LateStartTest {

    private final ManualClock clock = new ManualClock();

    @Test
    void aReleaseThatStartsAfterItsDeadlineIsReportedOnceAtItsStart() {
        List<String> misses = new ArrayList<>();
        MonitorListener listener = new MonitorListener() {
            @Override
            public void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedNs,
                                       boolean stillRunning) {
                misses.add(task.name() + " release " + releaseNs / 1_000_000 + " ms, deadline "
                        + deadlineNs / 1_000_000 + " ms, detected " + detectedNs / 1_000_000 + " ms"
                        + (stillRunning ? ", running" : ""));
            }
        };
        // 'hog' (registered first, so it runs first at 0) takes 5 ms; 'short' has a 2 ms deadline,
        // so its release 0 starts at 5 ms, 3 ms after its deadline.
        Monitor monitor = Monitor.builder(clock).listener(listener)
                .task("hog", Schedule.periodic(ms(100)), FnTask.of(now -> {
                    if (now == 0) {
                        clock.advance(ms(5));
                    }
                }))
                .task("short", new Schedule.Periodic(ms(10), 0, ms(2)), FnTask.of(now -> { }))
                .build();
        monitor.startStepped().runUntil(ms(10));
        Report report = monitor.stop();

        assertEquals(List.of("short release 0 ms, deadline 2 ms, detected 5 ms, running"), misses);
        assertEquals(1, report.task("short").misses(), "one miss, not one at the start and one at the end");
        assertEquals(1, report.task("short").runs(), "it still ran");
        assertEquals(0, report.task("hog").misses());
    }
}
