package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import io.rtaware.core.FnTask;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The once and continuous schedules on the step executor. */
class ScheduleKindsTest {

    private final ManualClock clock = new ManualClock();
    private final RecordingListener events = new RecordingListener();

    @Test
    void onceTaskRunsExactlyOnceAtItsOffsetAndFinishes() {
        List<Long> starts = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock).listener(events)
                .task("boot", new Schedule.Once(ms(7)), FnTask.of(starts::add)).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(100));

        assertEquals(List.of(ms(7)), starts, "a once task runs one time, at start + offset");
        assertFalse(step.step(), "nothing is left to release after the once task ran");
        assertEquals(1, events.count("state boot FINISHED"), "the once task ends FINISHED: " + events.events);
        Report report = monitor.stop();
        assertEquals(1, report.task("boot").releases(), "one release");
        assertEquals(1, report.task("boot").runs(), "one run");
        assertEquals(0, report.task("boot").misses(), "a once task has no deadline");
        assertEquals("once", report.task("boot").schedule(), "schedule kind");
    }

    @Test
    void continuousTaskRunsBackToBack() {
        List<Long> starts = new ArrayList<>();
        FnTask task = FnTask.of(now -> {
            starts.add(now);
            clock.advance(ms(3));
        });
        Monitor monitor = Monitor.builder(clock).task("socket", Schedule.continuous(), task).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(10));

        assertEquals(List.of(0L, ms(3), ms(6), ms(9)), starts, "each cycle starts when the previous returned");
        assertEquals(4, monitor.counters("socket").releases(), "each run of a continuous task is one release");
        assertEquals(0, monitor.counters("socket").misses(), "a continuous task has no deadline");
        assertEquals(ms(12), clock.nanos(), "the last cycle (9..12 ms) ran past the end of runUntil");
    }

    @Test
    void zeroDurationContinuousTaskIsReleasedEveryIdleStep() {
        List<Long> starts = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock).task("idle", Schedule.continuous(), FnTask.of(starts::add)).build();
        StepExecutor step = monitor.startStepped();
        long idle = step.idleStepNs();

        step.runUntil(5 * idle);

        assertEquals(List.of(0L, idle, 2 * idle, 3 * idle, 4 * idle), starts,
                "a cycle that takes no world time is released again idleStepNs later");
    }

    @Test
    void zeroDurationContinuousTaskStartedLateStillWaitsOneIdleStep() {
        // The periodic task runs first (registration order) for 2.5 ms, so the continuous task,
        // released at 0, starts 2.5 ms late; its zero-duration cycle must not be re-released at once.
        List<Long> starts = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock)
                .task("busy", new Schedule.Once(0), FnTask.of(now -> clock.advance(ms(2.5))))
                .task("idle", Schedule.continuous(), FnTask.of(starts::add)).build();
        StepExecutor step = monitor.startStepped();
        long idle = step.idleStepNs();

        step.runUntil(ms(2.5) + 3 * idle);

        assertEquals(List.of(ms(2.5), ms(2.5) + idle, ms(2.5) + 2 * idle), starts,
                "a zero-duration cycle is followed by an idle step even when it started late");
    }
}
