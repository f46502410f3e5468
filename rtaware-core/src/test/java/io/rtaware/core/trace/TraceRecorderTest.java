package io.rtaware.core.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.testing.FixedTaskInfo;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.StreamSupport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TraceRecorderTest {

    private static final long MS = 1_000_000;

    @TempDir
    Path dir;

    /** A counter value. */
    static final class Tick implements StateValue<Tick> {
        long n;

        @Override
        public void copyFrom(Tick source) {
            n = source.n;
        }
    }

    private static final Key<Tick> TICK = Key.of("tick", Tick.class, Tick::new);

    private static final class SimTask implements Task {
        private final ManualClock clock;
        private final long execNs;
        private final boolean produces;
        private final boolean consumes;
        private Output<Tick> out;

        SimTask(ManualClock clock, long execNs, boolean produces, boolean consumes) {
            this.clock = clock;
            this.execNs = execNs;
            this.produces = produces;
            this.consumes = consumes;
        }

        @Override
        public void initialize(TaskSetup setup) {
            if (produces) {
                out = setup.produce(TICK);
            }
            if (consumes) {
                setup.consume(TICK);
            }
        }

        @Override
        public void execute(long nowNs) {
            clock.advance(execNs);
            if (produces) {
                out.value().n++;
                out.publish();
            }
        }
    }

    private static List<JsonNode> events(JsonNode root, String ph, String name) {
        List<JsonNode> out = new ArrayList<>();
        for (JsonNode e : root.path("traceEvents")) {
            if (e.path("ph").asText().equals(ph) && (name == null || e.path("name").asText().equals(name))) {
                out.add(e);
            }
        }
        return out;
    }

    private static List<Double> field(List<JsonNode> events, String field) {
        return events.stream().map(e -> e.path(field).asDouble()).toList();
    }

    @Test
    void writesSlicesReleasesStaleRunsAndCommitsOnTheirTracks() throws Exception {
        ManualClock clock = new ManualClock();
        Monitor monitor = Monitor.builder(clock)
                .task("a", Schedule.periodic(Duration.ofMillis(10)), new SimTask(clock, 2 * MS, true, false))
                .task("c", Schedule.periodic(Duration.ofMillis(5)), new SimTask(clock, 0, false, true))
                .build();
        TraceRecorder trace = TraceRecorder.attach(monitor, 1000);
        monitor.startStepped().runUntil(40 * MS);
        monitor.stop();
        Path file = dir.resolve("trace.json");
        trace.write(file);

        JsonNode root = new ObjectMapper().readTree(file.toFile());
        List<String> threads = StreamSupport.stream(root.path("traceEvents").spliterator(), false)
                .filter(e -> e.path("name").asText().equals("thread_name"))
                .map(e -> e.path("pid").asInt() + "/" + e.path("tid").asInt() + "=" + e.path("args").path("name").asText())
                .toList();
        assertEquals(List.of("1/1=a", "1/2=c", "2/1=tick"), threads);

        // a: releases 0, 10, 20, 30, each 2 ms, committing at the end.
        List<JsonNode> aSlices = events(root, "X", "a");
        assertEquals(List.of(0.0, 10_000.0, 20_000.0, 30_000.0), field(aSlices, "ts"));
        assertEquals(List.of(2000.0, 2000.0, 2000.0, 2000.0), field(aSlices, "dur"));
        assertEquals(1, aSlices.get(0).path("tid").asInt());
        // c every 5 ms on one simulated core: the releases at 0, 10, 20, 30 wait for a.
        List<JsonNode> cSlices = events(root, "X", "c");
        assertEquals(List.of(2000.0, 5000.0, 12_000.0, 15_000.0, 22_000.0, 25_000.0, 32_000.0, 35_000.0),
                field(cSlices, "ts"));
        assertEquals(2000.0, cSlices.get(0).path("args").path("lateness_us").asDouble());
        List<Double> cReleases = events(root, "i", "release").stream().filter(e -> e.path("tid").asInt() == 2)
                .map(e -> e.path("ts").asDouble()).toList();
        assertEquals(List.of(0.0, 5000.0, 10_000.0, 15_000.0, 20_000.0, 25_000.0, 30_000.0, 35_000.0), cReleases);
        assertEquals(List.of(5000.0, 15_000.0, 25_000.0, 35_000.0), field(events(root, "i", "stale run"), "ts"));
        List<JsonNode> commits = events(root, "i", "commit");
        assertEquals(List.of(2000.0, 12_000.0, 22_000.0, 32_000.0), field(commits, "ts"));
        assertEquals(2, commits.get(0).path("pid").asInt());
        assertEquals(4, commits.get(3).path("args").path("generation").asInt());
        assertEquals(0, root.path("otherData").path("dropped_events").asLong());
        // 12 cycles + 4 stale runs + 4 commits
        assertEquals(20, root.path("otherData").path("recorded_events").asLong());
    }

    private static Monitor overrunning(ManualClock clock) {
        // exec 25 ms every 10 ms: release 0 runs 0..25 (miss at 25, releases 1, 2 skipped),
        // release 3 runs 30..55 (miss at 55, releases 4, 5 skipped).
        return Monitor.builder(clock)
                .task("m", Schedule.periodic(Duration.ofMillis(10)), new SimTask(clock, 25 * MS, false, false))
                .build();
    }

    @Test
    void deadlineMissesAndSkippedReleasesAreInstants() throws Exception {
        ManualClock clock = new ManualClock();
        Monitor monitor = overrunning(clock);
        TraceRecorder trace = TraceRecorder.attach(monitor, 100);
        monitor.startStepped().runUntil(60 * MS);
        monitor.stop();
        Path file = dir.resolve("misses.json");
        trace.write(file);
        JsonNode root = new ObjectMapper().readTree(file.toFile());
        List<JsonNode> misses = events(root, "i", "deadline miss");
        assertEquals(List.of(25_000.0, 55_000.0), field(misses, "ts"));
        assertEquals(15_000.0, misses.get(0).path("args").path("still_running_past_deadline_us").asDouble());
        List<JsonNode> skipped = events(root, "i", "skipped");
        assertEquals(List.of(25_000.0, 55_000.0), field(skipped, "ts"));
        assertEquals(2, skipped.get(1).path("args").path("releases").asInt());
        assertEquals(List.of(0.0, 30_000.0), field(events(root, "X", "m"), "ts"));
    }

    @Test
    void overflowKeepsTheNewestEventsAndCountsTheDropped() throws Exception {
        ManualClock clock = new ManualClock();
        Monitor monitor = overrunning(clock);
        TraceRecorder trace = TraceRecorder.attach(monitor, 4);
        monitor.startStepped().runUntil(60 * MS);
        monitor.stop();
        // Recorded in order: miss@25, cycle 0..25, skipped@25, miss@55, cycle 30..55, skipped@55.
        assertEquals(6, trace.recorded());
        assertEquals(2, trace.dropped());
        Path file = dir.resolve("small.json");
        trace.write(file);
        JsonNode root = new ObjectMapper().readTree(file.toFile());
        assertEquals(2, root.path("otherData").path("dropped_events").asLong());
        assertEquals(4, root.path("otherData").path("capacity_events").asLong());
        assertEquals(List.of(55_000.0), field(events(root, "i", "deadline miss"), "ts"));
        assertEquals(List.of(25_000.0, 55_000.0), field(events(root, "i", "skipped"), "ts"));
        assertEquals(List.of(30_000.0), field(events(root, "X", "m"), "ts"));
    }

    @Test
    void recordingDoesNotAllocate() {
        TraceRecorder trace = new TraceRecorder(1024, List.of("t"), List.of("k"), 0);
        TaskInfo task = new FixedTaskInfo("t", 0, Schedule.periodic(MS), List.of());
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        // Steady state: the least any of several rounds allocated (the first rounds include
        // class loading and JIT compilation on this thread).
        long least = Long.MAX_VALUE;
        for (int round = 0; round < 6; round++) {
            long before = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
            for (int i = 0; i < 100_000; i++) {
                trace.onCycle(task, i, i + 1, i + 2);
                trace.onCommit(task, 0, i, i + 2);
                trace.onStaleRun(task, i);
                trace.onDeadlineMiss(task, i, i + 1, i + 3, true);
                trace.onSkippedReleases(task, 1, i);
                trace.onExpiredInput(task, "k", 5, 1, i);
            }
            least = Math.min(least, mx.getThreadAllocatedBytes(Thread.currentThread().getId()) - before);
        }
        assertEquals(0, least, "bytes allocated by 600,000 recorded events");
    }
}
