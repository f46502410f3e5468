package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Adaptive periods on the manual clock: the rule of {@link AdaptivePolicy}, exactly. */
class AdaptivePeriodTest {

    private static final long MS = 1_000_000;
    /** Window of 4 releases, step x2, stale band 25..75%, headroom 50%. */
    private static final AdaptivePolicy POLICY = new AdaptivePolicy(4, 2.0, 75, 25, 50);

    /** A counter value. */
    static final class Tick implements StateValue<Tick> {
        long n;

        @Override
        public void copyFrom(Tick source) {
            n = source.n;
        }
    }

    private static final Key<Tick> TICK = Key.of("tick", Tick.class, Tick::new);

    /** Publishes a tick every cycle, or consumes one; simulates its execution time on the clock. */
    private static final class SimTask implements Task {
        private final ManualClock clock;
        private final long execNs;
        private final boolean producer;
        private Output<Tick> out;

        SimTask(ManualClock clock, long execNs, boolean producer) {
            this.clock = clock;
            this.execNs = execNs;
            this.producer = producer;
        }

        @Override
        public void initialize(TaskSetup setup) {
            if (producer) {
                out = setup.produce(TICK);
            } else {
                setup.consume(TICK);
            }
        }

        @Override
        public void execute(long nowNs) {
            clock.advance(execNs);
            if (producer) {
                out.value().n++;
                out.publish();
            }
        }
    }

    /** Records releases and period changes. */
    private static final class Log implements MonitorListener {
        final List<String> releases = new ArrayList<>();
        final List<PeriodChange> changes = new ArrayList<>();
        final List<Long> changeDecidedNs = new ArrayList<>();
        private final String task;

        Log(String task) {
            this.task = task;
        }

        @Override
        public void onCycle(TaskInfo t, long releaseNs, long startNs, long endNs) {
            if (t.name().equals(task)) {
                releases.add(Long.toString(releaseNs / MS));
            }
        }

        @Override
        public void onPeriodChange(TaskInfo t, PeriodChange change, long nowNs) {
            changes.add(change);
            changeDecidedNs.add(nowNs);
        }
    }

    @Test
    void missesPushThePeriodLongerAndReanchorTheGrid() {
        ManualClock clock = new ManualClock();
        Log log = new Log("a");
        Monitor monitor = Monitor.builder(clock).adaptivePeriods(POLICY)
                .task("a", Schedule.adaptive(Duration.ofMillis(10), Duration.ofMillis(10), Duration.ofMillis(40)),
                        new SimTask(clock, 12 * MS, true))
                .listener(log).build();
        monitor.startStepped().runUntil(130 * MS);
        monitor.stop();

        // Releases 0 and 2 run 12 ms each and miss; 1 and 3 are skipped: window of 4 releases,
        // 4 misses -> 20 ms, anchored at release 4 = 40 ms of the old grid. Then 40, 60, 80,
        // 100 meet their deadlines; the next window (4..7) holds: 12 ms is more than 50% of 10 ms.
        assertEquals(List.of("0", "20", "40", "60", "80", "100", "120"), log.releases);
        assertEquals(List.of(new PeriodChange("a", 40 * MS, 10 * MS, 20 * MS, PeriodChange.Reason.MISSES,
                4, 4, 2, 0, 12 * MS)), log.changes);
        assertEquals(List.of(32 * MS), log.changeDecidedNs);
        assertEquals(log.changes, monitor.periodHistory());
        assertEquals(20.0, monitor.report().task("a").periodMs());
        assertEquals(20.0, monitor.report().task("a").deadlineMs());
        assertEquals(4, monitor.report().task("a").misses());
    }

    @Test
    void freshInputsPullShorterUntilNyquistThenHysteresisHolds() {
        ManualClock clock = new ManualClock();
        Log log = new Log("c");
        Monitor monitor = Monitor.builder(clock).adaptivePeriods(POLICY)
                .task("p", Schedule.periodic(Duration.ofMillis(20)), new SimTask(clock, 0, true))
                .task("c", Schedule.adaptive(Duration.ofMillis(40), Duration.ofMillis(5), Duration.ofMillis(40)),
                        new SimTask(clock, MS, false))
                .listener(log).build();
        monitor.startStepped().runUntil(400 * MS);
        monitor.stop();

        // 0, 40, 80, 120: every read is new (p commits every 20 ms, first at equal times) and
        // 1 ms <= 50% of 20 ms -> 20 ms from 160. 160..220: all new -> 10 ms from 240. From then
        // on every other run is stale (50%, inside the 25..75% band): the period holds at 10 ms,
        // twice the input's rate.
        assertEquals(List.of(
                new PeriodChange("c", 160 * MS, 40 * MS, 20 * MS, PeriodChange.Reason.FRESH_WITH_HEADROOM, 4, 0, 4, 0, MS),
                new PeriodChange("c", 240 * MS, 20 * MS, 10 * MS, PeriodChange.Reason.FRESH_WITH_HEADROOM, 4, 0, 4, 0, MS)),
                log.changes);
        assertEquals(List.of("0", "40", "80", "120", "160", "180", "200", "220", "240", "250", "260", "270"),
                log.releases.subList(0, 12));
        assertEquals(10.0, monitor.report().task("c").periodMs());
    }

    @Test
    void staleRunsPushLongerUntilNyquistThenHold() {
        ManualClock clock = new ManualClock();
        Log log = new Log("c");
        Monitor monitor = Monitor.builder(clock).adaptivePeriods(POLICY)
                .task("p", Schedule.periodic(Duration.ofMillis(20)), new SimTask(clock, 0, true))
                .task("c", Schedule.adaptive(Duration.ofMillis(5), Duration.ofMillis(40)),
                        new SimTask(clock, MS, false))
                .listener(log).build();
        monitor.startStepped().runUntil(300 * MS);
        monitor.stop();

        // 0 new, 5, 10, 15 stale: 75% -> 10 ms from 20 ms; then new, stale, new, stale: holds.
        assertEquals(List.of(new PeriodChange("c", 20 * MS, 5 * MS, 10 * MS, PeriodChange.Reason.STALE, 4, 0, 4, 3, MS)),
                log.changes);
        assertEquals(List.of("0", "5", "10", "15", "20", "30", "40"), log.releases.subList(0, 7));
    }

    @Test
    void withoutThePolicyAnAdaptiveTaskKeepsItsInitialPeriod() {
        ManualClock clock = new ManualClock();
        Log log = new Log("a");
        Monitor monitor = Monitor.builder(clock)
                .task("a", Schedule.adaptive(Duration.ofMillis(10), Duration.ofMillis(40)),
                        new SimTask(clock, 12 * MS, true))
                .listener(log).build();
        monitor.startStepped().runUntil(100 * MS);
        monitor.stop();
        assertEquals(List.of(), log.changes);
        assertEquals(List.of("0", "20", "40", "60", "80"), log.releases);
        assertEquals(10.0, monitor.report().task("a").periodMs());
    }

    @Test
    void aBadRangeIsAConfigurationError() {
        ManualClock clock = new ManualClock();
        var builder = Monitor.builder(clock).task("a",
                Schedule.adaptive(Duration.ofMillis(50), Duration.ofMillis(10), Duration.ofMillis(40)),
                new SimTask(clock, 0, true));
        ConfigurationException e = org.junit.jupiter.api.Assertions.assertThrows(ConfigurationException.class,
                builder::build);
        assertEquals(List.of("task 'a' has period range 10ms..40ms and period 50ms; it needs 0 < min <= period <= max"),
                e.violations());
    }
}
