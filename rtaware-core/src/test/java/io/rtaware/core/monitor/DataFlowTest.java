package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.data.FeedStats;
import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.report.DataReport;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Latest-value data: stale runs, NEW/OLD/NONE with age, freshness, feed rate and intervals. */
class DataFlowTest {

    private static final Key<Counter> COUNT = Counter.key("count");
    private static final Key<Counter> OTHER = Counter.key("other");

    private final ManualClock clock = new ManualClock();
    private final RecordingListener events = new RecordingListener();

    /** A producer that commits an increasing counter each cycle, after {@code cycleMs} of work. */
    private FnTask producer(Key<Counter> key, double cycleMs) {
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        return new FnTask(s -> out[0] = s.produce(key), now -> {
            clock.advance(ms(cycleMs));
            out[0].value().value++;
            out[0].publish();
        });
    }

    /** What a consumer saw at one cycle. */
    record Seen(long nowNs, String status, long ageNs, long generation, long value, boolean expired) {
    }

    private static FnTask consumer(Key<Counter> key, Duration maxAge, List<Seen> seen) {
        @SuppressWarnings("unchecked")
        Input<Counter>[] in = new Input[1];
        return new FnTask(s -> in[0] = maxAge == null ? s.consume(key) : s.consume(key, maxAge), now -> seen.add(
                new Seen(now, in[0].status().name(), in[0].ageNs(), in[0].generation(), in[0].value().value,
                        in[0].isExpired())));
    }

    @Test
    void consumerThreeTimesFasterThanItsProducerHasTwoStaleRunsInThree() {
        List<Seen> seen = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock).listener(events)
                .task("producer", Schedule.periodic(ms(30)), producer(COUNT, 0))
                .task("consumer", Schedule.periodic(ms(10)), consumer(COUNT, null, seen)).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(90));

        assertEquals(9, monitor.counters("consumer").runs(), "consumer runs at 0, 10, ..., 80 ms");
        assertEquals(6, monitor.counters("consumer").staleRuns(),
                "new data only at 0, 30, 60 ms: the other six runs are stale");
        assertEquals(List.of("stale consumer at=" + ms(10), "stale consumer at=" + ms(20), "stale consumer at=" + ms(40),
                        "stale consumer at=" + ms(50), "stale consumer at=" + ms(70), "stale consumer at=" + ms(80)),
                events.events.stream().filter(e -> e.startsWith("stale")).toList(), "stale-run events, at cycle start");
        assertEquals(0, monitor.counters("producer").staleRuns(), "a task with no inputs is never stale");
        assertEquals(6, monitor.stop().task("consumer").staleRuns(), "stale runs in the report");
    }

    @Test
    void taskWithSeveralInputsIsStaleOnlyWhenNoneIsNew() {
        List<Seen> seen = new ArrayList<>();
        @SuppressWarnings("unchecked")
        Input<Counter>[] other = new Input[1];
        FnTask both = new FnTask(s -> {
            s.consume(COUNT);
            other[0] = s.consume(OTHER);
        }, now -> seen.add(new Seen(now, other[0].status().name(), 0, 0, 0, false)));
        Monitor monitor = Monitor.builder(clock)
                .task("fast", Schedule.periodic(ms(20)), producer(COUNT, 0))
                .task("slow", Schedule.periodic(ms(40)), producer(OTHER, 0))
                .task("both", Schedule.periodic(ms(10)), both).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(80));

        // New data at 0 (both), 20 (count), 40 (both), 60 (count); stale at 10, 30, 50, 70.
        assertEquals(4, monitor.counters("both").staleRuns(), "stale only when neither input changed");
    }

    @Test
    void readStatusIsNoneThenNewThenOldWithExactAge() {
        List<Seen> seen = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock)
                .task("producer", Schedule.periodic(Duration.ofMillis(20), Duration.ofMillis(5), Duration.ofMillis(20)),
                        producer(COUNT, 1))
                .task("consumer", Schedule.periodic(ms(10)), consumer(COUNT, null, seen)).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(50));

        // The producer starts at 5, 25, 45 ms and commits 1 ms later: at 6, 26, 46 ms.
        assertEquals(List.of(
                        new Seen(0, "NONE", Long.MAX_VALUE, 0, 0, false),
                        new Seen(ms(10), "NEW", ms(4), 1, 1, false),
                        new Seen(ms(20), "OLD", ms(14), 1, 1, false),
                        new Seen(ms(30), "NEW", ms(4), 2, 2, false),
                        new Seen(ms(40), "OLD", ms(14), 2, 2, false)), seen,
                "status, age (cycle start - commit time), generation and value at each consumer cycle");
    }

    @Test
    void unpublishedCyclesCommitNothing() {
        List<Seen> seen = new ArrayList<>();
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        FnTask sometimes = new FnTask(s -> out[0] = s.produce(COUNT), now -> {
            out[0].value().value = now;
            if (now == ms(10)) {
                out[0].publish();
            }
        });
        Monitor monitor = Monitor.builder(clock)
                .task("producer", Schedule.periodic(ms(10)), sometimes)
                .task("consumer", Schedule.periodic(ms(10)), consumer(COUNT, null, seen)).build();
        monitor.startStepped().runUntil(ms(40));

        assertEquals(List.of("NONE", "NEW", "OLD", "OLD"), seen.stream().map(Seen::status).toList(),
                "only the published cycle at 10 ms is committed");
        assertEquals(ms(10), seen.get(3).value(), "the consumer keeps the committed value, not later buffer writes");
        assertEquals(1, out[0].commits(), "the output counts its commits");
        assertEquals(1, monitor.feed("count").commits(), "the store counts one commit");
    }

    @Test
    void inputOlderThanItsMaxAgeIsExpiredAndCounted() {
        List<Seen> seen = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock).listener(events)
                .task("producer", Schedule.periodic(Duration.ofMillis(20), Duration.ofMillis(5), Duration.ofMillis(20)),
                        producer(COUNT, 1))
                .task("consumer", Schedule.periodic(ms(10)), consumer(COUNT, Duration.ofMillis(12), seen))
                .task("relaxed", Schedule.periodic(ms(10)), consumer(COUNT, null, new ArrayList<>())).build();
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(50));

        assertEquals(List.of(true, false, true, false, true), seen.stream().map(Seen::expired).toList(),
                "NONE (never written) and 14 ms-old values are expired with max age 12 ms; 4 ms-old ones are not");
        assertEquals(3, monitor.counters("consumer").expiredReads(), "expired reads counted");
        assertEquals(List.of(
                        "expired consumer count age=" + Long.MAX_VALUE + " max=" + ms(12) + " at=0",
                        "expired consumer count age=" + ms(14) + " max=" + ms(12) + " at=" + ms(20),
                        "expired consumer count age=" + ms(14) + " max=" + ms(12) + " at=" + ms(40)),
                events.events.stream().filter(e -> e.startsWith("expired")).toList(), "onExpiredInput events");
        assertEquals(0, monitor.counters("relaxed").expiredReads(), "an input without max age never expires");
    }

    @Test
    void maxAgeExactlyEqualToTheAgeIsNotExpired() {
        List<Seen> seen = new ArrayList<>();
        Monitor monitor = Monitor.builder(clock)
                .task("producer", Schedule.periodic(ms(20)), producer(COUNT, 0))
                .task("consumer", Schedule.periodic(ms(10)), consumer(COUNT, Duration.ofMillis(10), seen)).build();
        monitor.startStepped().runUntil(ms(20));
        assertEquals(List.of(false, false), seen.stream().map(Seen::expired).toList(), "age 0 and age 10 ms with max 10 ms");
        assertEquals(ms(10), seen.get(1).ageNs(), "age at 10 ms");
    }

    @Test
    void producerCommittingEvery20msFeedsAt50HzWithExactIntervals() {
        Monitor monitor = Monitor.builder(clock)
                .task("producer", Schedule.periodic(ms(20)), producer(COUNT, 0))
                .task("a", Schedule.periodic(ms(10)), consumer(COUNT, null, new ArrayList<>()))
                .task("b", Schedule.periodic(ms(50)), consumer(COUNT, null, new ArrayList<>())).build();
        monitor.startStepped().runUntil(ms(200));

        FeedStats feed = monitor.feed("count");
        assertEquals(10, feed.commits(), "commits at 0, 20, ..., 180 ms");
        assertEquals(ms(20), feed.minIntervalNs(), "min interval");
        assertEquals(ms(20), feed.maxIntervalNs(), "max interval");
        assertEquals(ms(20), feed.meanIntervalNs(), 0.0, "mean interval");
        assertEquals(50.0, feed.rateHz(), 1e-9, "rate");

        DataReport data = monitor.stop().key("count");
        assertEquals("producer", data.producer(), "producer in the report");
        assertEquals(Set.of("a", "b"), Set.copyOf(data.consumers()), "consumers in the report");
        assertEquals(10, data.commits(), "commits in the report");
        assertEquals(50.0, data.rateHz(), 0.0, "rate_hz in the report");
        assertEquals(new DataReport.Interval(20.0, 20.0, 20.0), data.intervalMs(), "interval_ms in the report");
    }

    @Test
    void irregularCommitsGiveExactMinMeanMaxIntervals() {
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        Set<Long> publishAtMs = Set.of(0L, 10L, 40L, 50L, 90L);
        FnTask irregular = new FnTask(s -> out[0] = s.produce(COUNT), now -> {
            if (publishAtMs.contains(now / 1_000_000)) {
                out[0].publish();
            }
        });
        Monitor monitor = Monitor.builder(clock).task("irregular", Schedule.periodic(ms(10)), irregular).build();
        monitor.startStepped().runUntil(ms(100));

        FeedStats feed = monitor.feed("count");
        assertEquals(5, feed.commits(), "commits");
        assertEquals(ms(10), feed.minIntervalNs(), "intervals 10, 30, 10, 40 ms: min");
        assertEquals(ms(40), feed.maxIntervalNs(), "max");
        assertEquals(ms(22.5), feed.meanIntervalNs(), 0.0, "mean = 90 ms / 4 intervals");
        assertEquals(1000.0 / 22.5, feed.rateHz(), 1e-9, "rate = 1 / mean interval");
        Report report = monitor.stop();
        assertEquals(new DataReport.Interval(10.0, 22.5, 40.0), report.key("count").intervalMs(), "interval_ms");
        assertEquals(44.44, report.key("count").rateHz(), 0.0, "rate_hz rounded to 2 decimals");
        assertTrue(report.key("count").consumers().isEmpty(), "no consumers");
    }

    @Test
    void feedWithFewerThanTwoCommitsHasRateZero() {
        Monitor monitor = Monitor.builder(clock).task("p", new Schedule.Once(0), producer(COUNT, 0)).build();
        monitor.startStepped().runUntil(ms(10));
        FeedStats feed = monitor.feed("count");
        assertEquals(1, feed.commits(), "one commit");
        assertEquals(0.0, feed.rateHz(), 0.0, "no rate from one commit");
        assertEquals(0, feed.minIntervalNs(), "no interval from one commit");
        assertEquals(0, feed.maxIntervalNs(), "no max interval from one commit");
    }
}
