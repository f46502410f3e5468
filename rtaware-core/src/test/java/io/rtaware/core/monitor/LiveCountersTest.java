package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

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
        long runs = monitor.counters("worker").runs();
        assertEquals(ms(1), monitor.counters("worker").recentExecP99Ns(), runs + " cycles of 1 ms");

        workMs[0] = 3;
        step.runUntil(ms(10 * 200 + 10 * 10));
        assertEquals(runs + 10, monitor.counters("worker").runs());
        assertEquals(ms(3), monitor.counters("worker").recentExecP99Ns(), "10 slow cycles among the latest 210");

        // The p99 of 256 values is the third largest (the ceil(0.99 * 256)-th): exact, no buckets.
        workMs[0] = 2;
        int window = CycleStatistics.RECENT_EXEC_CYCLES;
        step.runUntil(ms(10 * 200 + 10 * 10 + 10 * (window - 3)));
        assertEquals(ms(3), monitor.counters("worker").recentExecP99Ns(),
                "the latest " + window + " cycles hold the last 3 slow ones");
        step.runUntil(ms(10 * 200 + 10 * 10 + 10 * (window - 2)));
        assertEquals(ms(2), monitor.counters("worker").recentExecP99Ns(),
                "one cycle later only 2 slow ones are left among the latest " + window);
        monitor.stop();
    }

    @Test
    void totalReleasesIsTheSumOfEveryTasksReleasesSkippedOnesIncluded() {
        Monitor monitor = Monitor.builder(clock)
                .task("fast", Schedule.periodic(ms(10)), new FnTask(s -> { }, now -> { }))
                .task("slow", Schedule.periodic(ms(30)), new FnTask(s -> { }, now -> clock.advance(ms(35))))
                .build();
        assertEquals(0, monitor.totalReleases(), "nothing released before the start");
        StepExecutor step = monitor.startStepped();
        step.runUntil(ms(300));
        long sum = monitor.counters("fast").releases() + monitor.counters("slow").releases();
        assertEquals(sum, monitor.totalReleases());
        assertEquals(true, monitor.counters("slow").skipped() > 0, "the 35 ms cycles of a 30 ms task skip");
        monitor.stop();
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
