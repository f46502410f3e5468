package io.rtaware.ros2.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.CycleOutcome;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.testing.FixedTaskInfo;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2msg.statistics.TimingStatistics;
import io.rtaware.ros2msg.value.MetricsMessage;
import java.lang.management.ManagementFactory;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The exporter's listener on a stepped monitor, drained on the test thread: what the monitor
 * reports reaches the statistics whole and in order, a full ring drops and counts, and the
 * listener allocates nothing.
 */
class TimingFeedTest {

    private static final long MS = 1_000_000L;

    /** Takes {@code workNs} of world time, or {@code longNs} in the cycle released at {@code longAtNs}. */
    private static final class Work implements Task {
        private final ManualClock clock;
        private final long workNs;
        private final long longAtNs;
        private final long longNs;
        private final boolean produces;
        private Output<LaserScan> out;
        private Input<LaserScan> in;

        Work(ManualClock clock, long workNs, long longAtNs, long longNs, boolean produces) {
            this.clock = clock;
            this.workNs = workNs;
            this.longAtNs = longAtNs;
            this.longNs = longNs;
            this.produces = produces;
        }

        @Override
        public void initialize(TaskSetup setup) {
            if (produces) {
                out = setup.produce(RobotKeys.LASER);
            } else {
                in = setup.consume(RobotKeys.LASER);
            }
        }

        @Override
        public void execute(long nowNs) {
            clock.advance(nowNs == longAtNs ? longNs : workNs);
            if (out != null) {
                out.publish();
            }
        }
    }

    @Test
    void aSteppedRunReachesTheStatisticsAsTheMonitorReportedIt() throws Exception {
        ManualClock clock = new ManualClock();
        // the sensor overruns at 500 ms: 150 ms of a 100 ms period, a miss and the release at 600 ms skipped
        Monitor monitor = Monitor.builder(clock)
                .task("sensor", Schedule.periodic(Duration.ofMillis(100)), new Work(clock, 4 * MS, 500 * MS, 150 * MS, true))
                .task("planner", Schedule.periodic(Duration.ofMillis(200)), new Work(clock, MS, -1, 0, false))
                .build();
        TimingFeed feed = TimingFeed.of(monitor.tasks());
        monitor.addListener(feed);
        Map<String, MetricsMessage> second = new HashMap<>();
        TimingStatistics statistics = new TimingStatistics(List.of("sensor", "planner"),
                List.of(List.of(), List.of("laser")), monitor.keyNames(), 0, 0, 0, (m, stopNs) -> {
                    MetricsMessage copy = new MetricsMessage(5);
                    for (int i = 0; i < m.count(); i++) {
                        copy.add(m.dataType(i), m.data(i));
                    }
                    second.put(m.measurementSourceName + " " + m.metricsSource, copy);
                });
        monitor.startStepped().runUntil(1100 * MS);
        monitor.stop();
        assertEquals(10 + 10 + 1 + 6, feed.drainInto(statistics),
                "10 commits and 10 cycles of the sensor, its skipped release, 6 cycles of the planner");
        statistics.finish(Long.MIN_VALUE);
        assertEquals(0, feed.dropped());
        // sensor in the first second: releases 0 to 900 ms but 600, 9 cycles, 1 skipped, 2 misses
        MetricsMessage misses = second.get("sensor deadline_misses");
        assertEquals(10, misses.valueOf(MetricsMessage.SAMPLE_COUNT));
        assertEquals(0.2, misses.valueOf(MetricsMessage.AVERAGE), 1e-12);
        assertEquals(150, second.get("sensor execution_time").valueOf(MetricsMessage.MAXIMUM));
        assertEquals(4, second.get("sensor execution_time").valueOf(MetricsMessage.MINIMUM));
        // planner at 0 (after the sensor: 4 ms late), 200, 400 (4 ms late each), 600 (still behind the
        // overrun: 50 ms late), 800 (4 ms late); every scan it reads is new and 0 ms old
        MetricsMessage lateness = second.get("planner release_lateness");
        assertEquals(5, lateness.valueOf(MetricsMessage.SAMPLE_COUNT));
        assertEquals(50, lateness.valueOf(MetricsMessage.MAXIMUM));
        assertEquals(5, second.get("laser message_age").valueOf(MetricsMessage.SAMPLE_COUNT));
        assertEquals(0, second.get("laser message_age").valueOf(MetricsMessage.MAXIMUM));
        assertEquals(0, second.get("planner input_age").valueOf(MetricsMessage.MAXIMUM));
    }

    /** A task of two inputs, as the monitor describes it. */
    private static final TaskInfo TWO_INPUTS = new FixedTaskInfo("t", 0, Schedule.continuous(), List.of("a", "b"));

    @Test
    void aFullRingDropsAndCountsAndTheListenerAllocatesNothing() throws Exception {
        TimingFeed feed = TimingFeed.of(List.of(TWO_INPUTS));
        long[] generations = {1, 2};
        for (int i = 0; i < TimingFeed.SLOTS_PER_TASK + 10; i++) {
            feed.onCycleRecord(TWO_INPUTS, CycleOutcome.OK, i, i, i + 1, generations);
        }
        assertEquals(10, feed.dropped());
        TimingStatistics statistics = new TimingStatistics(List.of("t"), List.of(List.of("a", "b")),
                List.of("a", "b"), 0, 0, 0, (m, stopNs) -> { });
        assertEquals(TimingFeed.SLOTS_PER_TASK, feed.drainInto(statistics));

        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assumeTrue(threads.isThreadAllocatedMemorySupported(), "thread allocation counting unsupported");
        long id = Thread.currentThread().getId();
        long least = Long.MAX_VALUE;
        for (int round = 0; round < 20 && least != 0; round++) { // a round can catch the runtime's own
            long before = threads.getThreadAllocatedBytes(id);
            for (int i = 0; i < 1000; i++) {
                feed.onCommit(TWO_INPUTS, 0, i + 1, i);
                feed.onCycleRecord(TWO_INPUTS, CycleOutcome.MISS, i, i, i + 1, generations);
                feed.onSkippedReleases(TWO_INPUTS, 2, i + 1);
            }
            least = Math.min(least, threads.getThreadAllocatedBytes(id) - before);
            feed.drainInto(statistics);
        }
        assertEquals(0, least, "bytes the listener allocated for 3000 records");
    }
}
