package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.ros2msg.DiagnosticArrayCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.DiagnosticStatus;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code /diagnostics} in a recording: every task's figures in one message, sampled by the writer thread. */
class HealthRingTest {

    private static final long MS = 1_000_000L;

    @TempDir
    Path dir;

    @Test
    void theLastArrayCarriesEachTasksFinalFigures() throws Exception {
        ManualClock clock = new ManualClock();
        long[] cycle = {0};
        Task overrunning = new Task() {
            @Override
            public void initialize(TaskSetup setup) {
            }

            @Override
            public void execute(long nowNs) {
                clock.advance(cycle[0]++ == 2 ? 150 * MS : MS); // the third cycle overruns its 100 ms period
            }
        };
        Monitor monitor = Monitor.builder(clock).task("a", Schedule.periodic(Duration.ofMillis(100)), overrunning).build();
        Path file = dir.resolve("health.mcap");
        RunRecorder recorder = RecordingListener.attach(monitor, file, new RecordingPlan());
        monitor.startStepped().runUntil(1_000 * MS);
        clock.advanceTo(5_000 * MS); // past the next second: the writer's next pass samples the final counters
        RecordingStats stats = recorder.finish();
        assertNull(stats.error());

        List<DiagnosticArray> arrays = new ArrayList<>();
        List<String> types = new ArrayList<>();
        McapReader.open(file).read(new McapVisitor() {
            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                                int offset, int length) {
                if (channel.topic().equals(RunRecorder.DIAGNOSTICS_TOPIC)) {
                    DiagnosticArray array = new DiagnosticArray(4, 16);
                    new DiagnosticArrayCodec().decode(new CdrReader().wrap(data, offset, length), new Ros2Header(), array);
                    arrays.add(array);
                    types.add(channel.metadata().get("topic_type_hash"));
                }
            }
        });
        assertTrue(!arrays.isEmpty(), "at least the array after the run");
        assertEquals(Ros2Types.DIAGNOSTIC_ARRAY.typeHash(), types.get(0));
        DiagnosticStatus a = arrays.get(arrays.size() - 1).status(0);
        assertEquals("rtaware: task a", a.name.toString());
        // 10 releases in 1 s less the one skipped after the overrun (0.2 s to 0.351 s skips 0.3 s): 9 runs,
        // 2 misses (the late cycle and the skipped release).
        assertEquals("releases=10 runs=9 misses=2 miss_pct=20.000", values(a, "releases", "runs", "misses", "miss_pct"));
        assertTrue(a.message.toString().startsWith("2 misses (20.00%), 0 stale runs"), a.message.toString());
    }

    private static String values(DiagnosticStatus s, String... keys) {
        List<String> out = new ArrayList<>();
        for (String k : keys) {
            for (int i = 0; i < s.valueCount(); i++) {
                if (s.key(i).toString().equals(k)) {
                    out.add(k + "=" + s.value(i));
                }
            }
        }
        return String.join(" ", out);
    }
}
