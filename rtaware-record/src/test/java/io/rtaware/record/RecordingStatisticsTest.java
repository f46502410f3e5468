package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.ros2msg.MetricsMessageCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.value.MetricsMessage;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code /statistics} of a recording of a stepped run, read back from the file: a sensor at 100 ms
 * taking 3 ms and a planner at 250 ms taking 2 ms that reads it, on one manual clock, so every
 * value is known.
 */
class RecordingStatisticsTest {

    private static final Key<MotionRequest> REQUEST = Key.of("request", MotionRequest.class, MotionRequest::new);
    private static final long MS = 1_000_000L;
    private static final long S = 1_000_000_000L;

    @TempDir
    Path dir;

    /** A task that takes {@code workNs} of world time, producing or consuming the request. */
    private static final class Work implements Task {
        private final ManualClock clock;
        private final long workNs;
        private final boolean produces;
        private Output<MotionRequest> out;
        private Input<MotionRequest> in;

        Work(ManualClock clock, long workNs, boolean produces) {
            this.clock = clock;
            this.workNs = workNs;
            this.produces = produces;
        }

        @Override
        public void initialize(TaskSetup setup) {
            if (produces) {
                out = setup.produce(REQUEST);
            } else {
                in = setup.consume(REQUEST);
            }
        }

        @Override
        public void execute(long nowNs) {
            clock.advance(workNs);
            if (out != null) {
                out.value().request(0.1, 0);
                out.publish();
            }
        }
    }

    private record Window(String source, String metric, String unit, long startNs, long stopNs, long logTimeNs,
                          double average, double min, double max, double stddev, double count) {
    }

    @Test
    void everyTaskAndKeyHasItsMetricsEverySecondOfTheRecording() throws Exception {
        ManualClock clock = new ManualClock();
        Monitor monitor = Monitor.builder(clock)
                .task("sensor", Schedule.periodic(Duration.ofMillis(100)), new Work(clock, 3 * MS, true))
                .task("planner", Schedule.periodic(Duration.ofMillis(250)), new Work(clock, 2 * MS, false))
                .build();
        Path file = dir.resolve("run.mcap");
        RunRecorder recorder = RecordingListener.attach(monitor, file, new RecordingPlan());
        monitor.startStepped().runUntil(3500 * MS);
        monitor.stop();
        RecordingStats stats = recorder.finish();
        assertNull(stats.error());
        assertEquals(0, stats.dropped());

        List<Window> windows = new ArrayList<>();
        Map<String, String> statisticsMetadata = new HashMap<>();
        long[] wallStart = new long[1];
        McapReader.open(file).read(new McapVisitor() {
            @Override
            public void metadata(String name, Map<String, String> entries) {
                if (name.equals(RunRecorder.STATISTICS_METADATA)) {
                    statisticsMetadata.putAll(entries);
                } else if (name.equals("rtaware.run")) {
                    wallStart[0] = Long.parseLong(entries.get(RecordingPlan.WALL_CLOCK_START_NS));
                }
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                                int offset, int length) {
                if (!channel.topic().equals(RecordingPlan.STATISTICS_TOPIC)) {
                    return;
                }
                assertEquals(Ros2Types.METRICS_MESSAGE.typeHash(), channel.metadata().get("topic_type_hash"));
                MetricsMessage m = new MetricsMessage(5);
                new MetricsMessageCodec().decode(new CdrReader().wrap(data, offset, length), new Ros2Header(), m);
                windows.add(new Window(m.measurementSourceName.toString(), m.metricsSource.toString(),
                        m.unit.toString(), m.windowStartNs, m.windowStopNs, logTimeNs,
                        m.valueOf(MetricsMessage.AVERAGE), m.valueOf(MetricsMessage.MINIMUM),
                        m.valueOf(MetricsMessage.MAXIMUM), m.valueOf(MetricsMessage.STDDEV),
                        m.valueOf(MetricsMessage.SAMPLE_COUNT)));
            }
        });
        assertEquals(Map.of("window_ns", "1000000000", "windows", "3", "late_records", "0", "unmatched_ages", "0"),
                statisticsMetadata, "three whole seconds; the fourth, cut at 3.5 s, is not published");
        assertEquals(3 * (4 * 2 + 2), windows.size(), "4 metrics of 2 tasks, 2 of the key, each second");
        long start = wallStart[0]; // world time 0, when the recording started: the first window's start
        for (Window w : windows) {
            assertEquals(S, w.stopNs - w.startNs, w.toString());
            assertEquals(0, (w.startNs - start) % S, "windows aligned on the recording's start: " + w);
            assertEquals(w.stopNs, w.logTimeNs, "logged at the window's end: " + w);
        }

        // Second 0: both released at 0, the sensor first (registration order): 0-3 ms, commit at 3;
        // the planner 3-5 ms (3 ms late), its input 0 ms old; at 250 ms it reads the commit of 203 ms.
        assertWindow(windows, "sensor", "release_lateness", start + S, 0, 0, 0, 0, 10);
        assertWindow(windows, "sensor", "execution_time", start + S, 3, 3, 3, 0, 10);
        assertWindow(windows, "sensor", "deadline_misses", start + S, 0, 0, 0, 0, 10);
        assertWindow(windows, "sensor", "input_age", start + S, Double.NaN, Double.NaN, Double.NaN, Double.NaN, 0);
        assertWindow(windows, "planner", "release_lateness", start + S, 1.5, 0, 3, 1.5, 4);
        assertWindow(windows, "planner", "execution_time", start + S, 2, 2, 2, 0, 4);
        assertWindow(windows, "planner", "input_age", start + S, 23.5, 0, 47, 23.5, 4);
        assertWindow(windows, "planner", "deadline_misses", start + S, 0, 0, 0, 0, 4);
        assertWindow(windows, "request", "message_period", start + S, 100, 100, 100, 0, 9);
        assertWindow(windows, "request", "message_age", start + S, 23.5, 0, 47, 23.5, 4);
        assertWindow(windows, "request", "message_period", start + 2 * S, 100, 100, 100, 0, 10);
        Window unit = windows.stream().filter(w -> w.metric.equals("deadline_misses")).findFirst().orElseThrow();
        assertEquals("count", unit.unit);
        assertTrue(windows.stream().filter(w -> !w.metric.equals("deadline_misses")).allMatch(w -> w.unit.equals("ms")));
    }

    @Test
    void aSecondsStatisticsComeBeforeAnyLaterMessageInTheFile() throws Exception {
        // No reorder window: every message is written as soon as it arrives, but for what the
        // statistics of the second not yet published hold back (they are published a drain later).
        Path file = dir.resolve("ordered.mcap");
        RunRecorder recorder = new RunRecorder(file, List.of("a"), List.of(List.of()), List.of(),
                new RecordingPlan().reorderWindowNs(0).worldStartNs(0));
        recorder.cycle(0, RunRecorder.OK, 500 * MS, 500 * MS, 501 * MS, 0, null);
        recorder.cycle(0, RunRecorder.OK, 1200 * MS, 1200 * MS, 1201 * MS, 0, null);
        recorder.cycle(0, RunRecorder.OK, 2500 * MS, 2500 * MS, 2501 * MS, 0, null);
        RecordingStats stats = recorder.finish();
        assertNull(stats.error());
        assertEquals(0, stats.outOfOrder(), "the cycle at 1.201 s waited for the statistics of the first second");
        List<String> order = new ArrayList<>();
        McapReader.open(file).read(new McapVisitor() {
            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                                int offset, int length) {
                order.add(channel.topic() + "@" + logTimeNs / MS);
            }
        });
        assertEquals(List.of("/rtaware/timing/a@501", "/statistics@1000", "/statistics@1000", "/statistics@1000",
                "/statistics@1000", "/rtaware/timing/a@1201", "/statistics@2000", "/statistics@2000",
                "/statistics@2000", "/statistics@2000", "/rtaware/timing/a@2501"), order);
    }

    private static void assertWindow(List<Window> windows, String source, String metric, long stopNs, double average,
                                     double min, double max, double stddev, long count) {
        Window w = windows.stream().filter(x -> x.source.equals(source) && x.metric.equals(metric) && x.stopNs == stopNs)
                .findFirst().orElseThrow(() -> new AssertionError("no " + source + " " + metric + " to " + stopNs));
        String what = source + " " + metric + ": " + w;
        assertEquals(count, w.count, what);
        assertEquals(average, w.average, 1e-12, what);
        assertEquals(min, w.min, 1e-12, what);
        assertEquals(max, w.max, 1e-12, what);
        assertEquals(stddev, w.stddev, 1e-12, what);
    }
}
