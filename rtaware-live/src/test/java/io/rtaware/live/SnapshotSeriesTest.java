package io.rtaware.live;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import java.time.Duration;
import java.util.function.LongUnaryOperator;
import org.junit.jupiter.api.Test;

/**
 * The strip charts' data in the snapshot, exactly, on stepped time: per task and per half second
 * of world time, the largest release lateness and execution time and the misses.
 */
class SnapshotSeriesTest {

    private static final long MS = 1_000_000L;

    private final ManualClock clock = new ManualClock();

    /** A task that takes, on the manual clock, the time its script gives its n-th cycle. */
    private final class Scripted implements Task {
        private final LongUnaryOperator execMsOfCycle;
        private long cycle;

        Scripted(LongUnaryOperator execMsOfCycle) {
            this.execMsOfCycle = execMsOfCycle;
        }

        @Override
        public void initialize(TaskSetup setup) {
        }

        @Override
        public void execute(long nowNs) {
            clock.advance(execMsOfCycle.applyAsLong(cycle++) * MS);
        }
    }

    private SnapshotBuilder builder(Monitor monitor) {
        SnapshotBuilder builder = new SnapshotBuilder(monitor, null, clock.nanos());
        monitor.addListener(builder.series());
        return builder;
    }

    @Test
    void eachHalfSecondHasTheLargestLatenessAndExecutionTimeAndTheMisses() {
        // a: every 100 ms, 20 ms of work, but 250 ms for its release at 300 ms (missing its 400 ms
        // deadline; the releases at 400 and 500 ms are skipped, counted when it ends at 550 ms).
        // b: every 500 ms, 1 ms of work, released with a (which runs first) or during a's overrun.
        Monitor monitor = Monitor.builder(clock)
                .task("a", Schedule.periodic(Duration.ofMillis(100)), new Scripted(n -> n == 3 ? 250 : 20))
                .task("b", Schedule.periodic(Duration.ofMillis(500)), new Scripted(n -> 1))
                .build();
        SnapshotBuilder builder = builder(monitor);
        monitor.startStepped().runUntil(2_000 * MS);

        JsonNode s = builder.build("running", null, null);
        assertEquals(0.5, s.path("series_bin_s").asDouble());
        assertEquals(0.0, s.path("series_from_s").asDouble());
        JsonNode a = s.path("tasks").get(0).path("series");
        // Bins [0, 0.5 s), [0.5, 1), [1, 1.5), [1.5, 2), and the one just begun at 2 s (no release yet).
        assertEquals("[0.0,0.0,0.0,0.0,null]", a.path("lateness_max_ms").toString());
        assertEquals("[250.0,20.0,20.0,20.0,null]", a.path("exec_max_ms").toString());
        assertEquals("[1,2,0,0,0]", a.path("misses").toString(), "the late cycle, then the two skipped releases");
        assertEquals(0, a.path("lost_cycles").asLong());
        JsonNode b = s.path("tasks").get(1).path("series");
        // At 0, 1 and 1.5 s b waits for a's 20 ms; at 0.5 s for the end of a's overrun, at 550 ms.
        assertEquals("[20.0,50.0,20.0,20.0,null]", b.path("lateness_max_ms").toString());
        assertEquals("[1.0,1.0,1.0,1.0,null]", b.path("exec_max_ms").toString());
        assertEquals("[0,0,0,0,0]", b.path("misses").toString());
    }

    @Test
    void theWindowIsTheLastMinuteOfWorldTime() {
        Monitor monitor = Monitor.builder(clock)
                .task("a", Schedule.periodic(Duration.ofMillis(100)), new Scripted(n -> n / 10)) // n/10 ms: 1 s = 10 cycles
                .build();
        SnapshotBuilder builder = builder(monitor);
        monitor.startStepped().runUntil(70_000 * MS);

        JsonNode s = builder.build("running", null, null);
        // 70 s: bin 140 has begun; the window is its 120 bins from bin 21, at 10.5 s.
        assertEquals(10.5, s.path("series_from_s").asDouble());
        JsonNode exec = s.path("tasks").get(0).path("series").path("exec_max_ms");
        assertEquals(TimingSeries.WINDOW_BINS, exec.size());
        // Bin 21 holds the releases 10.5 s to 10.9 s, cycles 105 to 109: 10 ms of work at most.
        assertEquals(10.0, exec.get(0).asDouble());
        // Bin 139 holds cycles 695 to 699: 69 ms.
        assertEquals(69.0, exec.get(TimingSeries.WINDOW_BINS - 2).asDouble());
        assertEquals(true, exec.get(TimingSeries.WINDOW_BINS - 1).isNull(), "bin 140 has no release yet");
    }

    @Test
    void cyclesOverwrittenBeforeThePublisherTookThemAreCountedNotDrawn() {
        Monitor monitor = Monitor.builder(clock)
                .task("a", Schedule.periodic(Duration.ofMillis(1)), new Scripted(n -> 0))
                .build();
        SnapshotBuilder builder = builder(monitor);
        monitor.startStepped().runUntil(5_000 * MS);

        JsonNode a = builder.build("running", null, null).path("tasks").get(0).path("series");
        // 5000 cycles, the ring holds the last 4096: cycles 0 to 903 were lost.
        assertEquals(5_000 - TimingSeries.RING_SLOTS, a.path("lost_cycles").asLong());
        assertEquals(true, a.path("exec_max_ms").get(0).isNull(), "bin 0 (cycles 0 to 499): all lost");
        assertEquals(0.0, a.path("exec_max_ms").get(1).asDouble(), "bin 1 keeps cycles 904 to 999");
    }
}
