package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.util.List;
import org.junit.jupiter.api.Test;

/** What observers read while the monitor runs: the live execution-time p99 and the key graph. */
class LiveCountersTest {

    private static final Key<Counter> COUNT = Counter.key("count");

    private final ManualClock clock = new ManualClock();

    @Test
    void recentExecP99FollowsTheLatestCyclesOnly() {
        long[] workMs = {1};
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        Monitor monitor = Monitor.builder(clock)
                .task("worker", Schedule.periodic(ms(10)), new FnTask(s -> out[0] = s.produce(COUNT), now -> {
                    clock.advance(ms(workMs[0]));
                    out[0].publish();
                }))
                .task("reader", Schedule.periodic(ms(20)), new FnTask(s -> s.consume(COUNT), now -> { }))
                .build();
        assertEquals(0, monitor.counters("worker").recentExecP99Ns(), "no cycle yet");
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(10 * 200));
        assertWithinHistogramPrecision(ms(1), monitor.counters("worker").recentExecP99Ns(), "200 cycles of 1 ms");

        workMs[0] = 3;
        step.runUntil(ms(10 * 200 + 10 * 10));
        assertWithinHistogramPrecision(ms(3), monitor.counters("worker").recentExecP99Ns(),
                "10 slow cycles among the latest 210 are above p99");

        workMs[0] = 2;
        int window = CycleStatistics.RECENT_EXEC_CYCLES;
        step.runUntil(ms(10 * 200 + 10 * 10 + 10 * window));
        assertWithinHistogramPrecision(ms(3), monitor.counters("worker").recentExecP99Ns(),
                "the window filled by this read holds the 10 slow cycles and 128 of 2 ms");
        step.runUntil(ms(10 * 200 + 10 * 10 + 10 * 2 * window));
        assertWithinHistogramPrecision(ms(2), monitor.counters("worker").recentExecP99Ns(),
                "two full windows later the slow cycles have left");
        monitor.stop();
    }

    /** HdrHistogram keeps two significant digits: a value reads back within 1% above it. */
    private static void assertWithinHistogramPrecision(long expectedNs, long actualNs, String message) {
        assertTrue(actualNs >= expectedNs && actualNs <= expectedNs + expectedNs / 100,
                message + ": expected " + expectedNs + " ns to 2 significant digits, got " + actualNs);
    }

    @Test
    void producerAndConsumersOfAKey() {
        Monitor monitor = Monitor.builder(clock)
                .task("a", Schedule.periodic(ms(10)), new FnTask(s -> s.produce(COUNT), now -> { }))
                .task("b", Schedule.periodic(ms(20)), new FnTask(s -> s.consume(COUNT), now -> { }))
                .task("c", Schedule.periodic(ms(40)), new FnTask(s -> s.consume(COUNT), now -> { }))
                .build();
        assertEquals("a", monitor.producer("count"));
        assertEquals(List.of("b", "c"), monitor.consumers("count"));
        assertThrows(IllegalArgumentException.class, () -> monitor.consumers("nope"));
    }
}
