package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.FnTask;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Release grid, deadline misses and skipped releases of periodic tasks, exactly, on the manual clock. */
class PeriodicTimingTest {

    private final ManualClock clock = new ManualClock();
    private final RecordingListener events = new RecordingListener();

    private static Schedule.Periodic periodic(long periodMs, long offsetMs, long deadlineMs) {
        return Schedule.periodic(Duration.ofMillis(periodMs), Duration.ofMillis(offsetMs), Duration.ofMillis(deadlineMs));
    }

    /** A task whose cycle k takes durationsMs[k] ms of world time (0 after the array's end). */
    private FnTask timed(List<Long> startsNs, long... durationsMs) {
        return FnTask.of(now -> {
            int k = startsNs.size();
            startsNs.add(now);
            if (k < durationsMs.length) {
                clock.advance(ms(durationsMs[k]));
            }
        });
    }

    private static List<Long> msList(long... millis) {
        List<Long> out = new ArrayList<>();
        for (long m : millis) {
            out.add(ms(m));
        }
        return out;
    }

    private static void assertReleasesAreRunsPlusSkipped(TaskCounters c) {
        assertEquals(c.runs() + c.skipped(), c.releases(), "releases must equal runs + skipped: " + c);
    }

    @Test
    void releasesFollowTheAbsoluteGridFromTheOffset() {
        List<Long> starts = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock).task("grid", periodic(10, 3, 10), timed(starts, 2, 2, 2, 2, 2)).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(50));

        assertEquals(msList(3, 13, 23, 33, 43), starts,
                "periodic(10ms, offset 3ms) must start exactly at 3, 13, 23, ... ms, without drift from 2 ms cycles");
        TaskCounters c = monitor.counters("grid");
        assertEquals(5, c.releases(), "releases in [0, 50) ms");
        assertEquals(0, c.misses(), "2 ms cycles never miss a 10 ms deadline");
        assertEquals(ms(50), clock.nanos(), "runUntil leaves the clock at its end");
    }

    @Test
    void gridIsFixedAtTheMonitorStartNotAtClockZero() {
        ManualClock late = new ManualClock(ms(1000));
        List<Long> starts = new ArrayList<>();
        Monitor monitor = Monitor.builder(late).task("grid", periodic(10, 3, 10), FnTask.of(starts::add)).build();
        StepExecutor step = monitor.startStepped();

        step.runFor(ms(25));

        assertEquals(msList(1003, 1013, 1023), starts, "release k = start + offset + k * period");
    }

    @Test
    void deadlineMissIsReportedWhileTheCycleIsStillRunning() {
        List<RecordingListener.Miss> seenInsideExecute = new ArrayList<>();
        FnTask task = FnTask.of(now -> {
            clock.advance(ms(15));
            seenInsideExecute.addAll(events.misses); // still inside the cycle
        });
        Monitor monitor = Monitor.builder(clock).listener(events).task("slow", Schedule.periodic(ms(10)), task).build();
        StepExecutor step = monitor.startStepped();

        step.step();

        assertEquals(List.of(new RecordingListener.Miss("slow", 0, ms(10), ms(15), true)), seenInsideExecute,
                "the miss must be reported at the advance past the deadline, before execute returns");
        assertEquals(1, events.misses.size(), "the miss is reported once, not again when the cycle returns: " + events.misses);
        TaskCounters c = monitor.counters("slow");
        assertEquals(1, c.skipped(), "the cycle ended at 15 ms, so release 1 (10 ms) was skipped");
        assertEquals(2, c.misses(), "one deadline miss plus one skipped release");
    }

    @Test
    void deadlineMissIsDetectedAtTheFirstAdvancePastTheDeadlineNotAtIt() {
        List<Long> missCountAfterEachMs = new ArrayList<>();
        FnTask task = FnTask.of(now -> {
            for (int i = 0; i < 12; i++) {
                clock.advance(ms(1));
                missCountAfterEachMs.add((long) events.misses.size());
            }
        });
        Monitor monitor = Monitor.builder(clock).listener(events).task("creep", Schedule.periodic(ms(10)), task).build();
        monitor.startStepped().step();

        assertEquals(List.of(0L, 0L, 0L, 0L, 0L, 0L, 0L, 0L, 0L, 0L, 1L, 1L), missCountAfterEachMs,
                "at exactly 10 ms the cycle is on time; the miss appears at 11 ms and only once");
        assertEquals(ms(11), events.misses.get(0).detectedNs(), "detected at the first advance past the deadline");
    }

    @Test
    void cycleEndingAtItsDeadlineIsOnTimeAndOneNanosecondLaterIsAMiss() {
        List<Long> starts = new ArrayList<>();
        FnTask task = FnTask.of(now -> {
            starts.add(now);
            clock.advance(starts.size() == 1 ? ms(10) : ms(10) + 1);
        });
        Monitor monitor = Monitor.builder(clock).listener(events).task("edge", Schedule.periodic(ms(10)), task).build();
        StepExecutor step = monitor.startStepped();
        step.step();
        assertEquals(0, monitor.counters("edge").misses(), "a cycle ending exactly at its deadline is not a miss");
        step.step();
        assertEquals(msList(0, 10), starts, "a cycle ending exactly on the next grid point does not skip it");
        assertEquals(1, events.misses.size(), "the second cycle ended 1 ns late: one miss");
        assertEquals(1, monitor.counters("edge").skipped(), "ending 1 ns after grid point 2 skips it");
        assertEquals(2, monitor.counters("edge").misses(), "the late cycle's miss (counted once) plus the skipped release");
    }

    @Test
    void missedReleaseIsCountedOncePerSkippedPeriodWithoutCatchUpBurst() {
        List<Long> starts = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock).listener(events)
                .task("overrun", Schedule.periodic(ms(10)), timed(starts, 35)).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(60));

        assertEquals(msList(0, 40, 50), starts,
                "after a 35 ms cycle the next run is at the next grid point (40 ms), with no catch-up runs");
        TaskCounters c = monitor.counters("overrun");
        assertEquals(6, c.releases(), "releases at 0..50 ms: 3 run + 3 skipped");
        assertEquals(3, c.runs(), "runs");
        assertEquals(3, c.skipped(), "releases 1, 2, 3 (10, 20, 30 ms) were skipped");
        assertEquals(4, c.misses(), "the late cycle's own miss plus one per skipped release");
        assertReleasesAreRunsPlusSkipped(c);
        assertEquals(List.of("skipped overrun 3 at=" + ms(35)),
                events.events.stream().filter(e -> e.startsWith("skipped")).toList(),
                "one skip event carrying the count 3, at the end of the late cycle");

        Report report = monitor.stop();
        TaskReport t = report.task("overrun");
        assertEquals(100.0 * 4 / 6, t.missPct(), 0.005, "miss_pct = 100 * misses / releases");
        assertEquals(66.67, t.missPct(), 0.0, "miss_pct is rounded to two decimals");
        assertEquals(66.67, report.missesTotalPct(), 0.0, "the only task's misses over its releases");
    }

    @Test
    void cycleEndingExactlyOnAGridPointDoesNotSkipThatPoint() {
        List<Long> starts = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock).task("exact", Schedule.periodic(ms(10)), timed(starts, 20, 30)).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(60));

        assertEquals(msList(0, 20, 50), starts,
                "a 20 ms cycle skips only release 1 and runs release 2 at 20 ms; a 30 ms cycle from 20 ms skips 3 and 4");
        TaskCounters c = monitor.counters("exact");
        assertEquals(3, c.skipped(), "releases 1, 3 and 4 were skipped");
        assertEquals(5, c.misses(), "two late cycles plus three skipped releases");
        assertEquals(6, c.releases(), "grid points 0..50 ms");
        assertReleasesAreRunsPlusSkipped(c);
    }

    @Test
    void deadlineShorterThanPeriodMissesWithoutSkipping() {
        List<Long> starts = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock).listener(events)
                .task("tight", periodic(10, 0, 4), timed(starts, 5, 4, 6)).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(40));

        assertEquals(msList(0, 10, 20, 30), starts, "cycles shorter than the period never skip");
        assertEquals(List.of(new RecordingListener.Miss("tight", 0, ms(4), ms(5), true),
                        new RecordingListener.Miss("tight", ms(20), ms(24), ms(26), true)), events.misses,
                "5 ms and 6 ms cycles miss a 4 ms deadline; a 4 ms cycle does not");
        TaskCounters c = monitor.counters("tight");
        assertEquals(2, c.misses(), "misses");
        assertEquals(0, c.skipped(), "skipped");
        assertEquals(4, c.releases(), "releases");
    }

    @Test
    void latenessIsStartMinusScheduledRelease() {
        // Two tasks released at 0: the second starts after the first's 3 ms cycle, 3 ms late.
        List<Long> firstStarts = new ArrayList<>();
        List<Long> secondStarts = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock)
                .task("first", Schedule.periodic(ms(10)), timed(firstStarts, 3, 3))
                .task("second", Schedule.periodic(ms(10)), FnTask.of(secondStarts::add)).build();
        StepExecutor step = monitor.startStepped();
        step.runUntil(ms(20));

        assertEquals(msList(3, 13), secondStarts, "tasks share one simulated core, in registration order on ties");
        Report report = monitor.stop();
        assertEquals(3000.0, report.task("second").latenessUs().max(), 0.0, "lateness max is exactly 3 ms");
        assertEquals(3000.0, report.task("second").latenessUs().mean(), 0.0, "lateness mean is exactly 3 ms");
        assertEquals(0.0, report.task("first").latenessUs().max(), 0.0, "the first task is never late");
        assertEquals(3000.0, report.task("first").execUs().max(), 0.0, "exec max is exactly 3 ms");
        assertTrue(report.task("second").execUs().max() == 0.0, "zero-duration cycles have exec time 0");
    }
}
