package io.rtaware.app.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import io.rtaware.app.run.FoxgloveReadersCheck;
import io.rtaware.app.run.Ros2ProfileCheck;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 28: {@code bench --record} writes the same kind of file as {@code run --record}: the MCAP
 * {@code ros2} profile, Unix-epoch log times in order, read by rosbags, the Python mcap reader and
 * Foxglove's TypeScript readers.
 */
class BenchRecordingTest {

    @TempDir
    Path dir;

    @Test
    void aBenchRecordingIsARos2BagInLogTimeOrderThatRosbagsDecodes() throws Exception {
        Path file = dir.resolve("bench.mcap");
        CliRun run = CliRun.of("bench", "--tasks", "4", "--period", "1ms", "--work", "0", "--duration", "2s",
                "--quiet", "--record", file.toString());
        assertEquals(0, run.status(), run.err());
        assertTrue(run.out().contains("recording written to " + file), run.out());
        String checked = Ros2ProfileCheck.run(file);
        assertTrue(checked.contains("rosbags AnyReader deserialized all"), checked);
        assertTrue(checked.contains("release_lateness, execution_time, input_age, deadline_misses of every task "
                + "(t1, t2, t3, t4)"), "issue 37: /statistics of every task, every second: " + checked);
        assertTrue(checked.contains("/statistics equals what the timing and key channels give"), checked);
        String foxglove = FoxgloveReadersCheck.run(file);
        assertTrue(foxglove.contains("McapStreamReader decoded all"), foxglove);
        CliRun inspect = CliRun.of("inspect", file.toString());
        assertEquals(0, inspect.status(), inspect.err());
        assertTrue(inspect.out().contains("rtaware_msgs/msg/TaskCycle"), inspect.out());
        assertTrue(!inspect.out().contains("/ground_truth"), "no channel a bench never writes: " + inspect.out());
        assertTrue(!inspect.out().contains("/clock"), "no /clock on wall time: " + inspect.out());
    }

    /**
     * Issue 34: the bench case of the issue, recorded, and its advice checked by replay. A bench's
     * world time is the machine's monotonic clock: the replay starts where the recording does (it
     * replayed from 0, an uptime's worth of releases), and it has no data task.
     */
    @Test
    void analyzeVerifyReplaysABenchRecording() {
        Path file = dir.resolve("chain.mcap");
        CliRun run = CliRun.of("bench", "--spec", "a:10ms:2ms,b:50ms:20ms", "--chain", "--duration", "2s",
                "--quiet", "--record", file.toString());
        assertEquals(0, run.status(), run.err());
        CliRun check = CliRun.of("analyze", "--verify", file.toString());
        assertEquals(0, check.status(), check.err());
        String row = check.out().lines().filter(l -> l.startsWith("  a            10ms -> ")).findFirst()
                .orElseThrow(() -> new AssertionError(check.out()));
        long releasesBefore = Long.parseLong(row.substring(33).trim().split("\\s+")[0]);
        assertTrue(releasesBefore > 150 && releasesBefore < 500, "2 s of warm-up and 2 s of run at 10 ms: " + row);
        assertTrue(check.out().lines().anyMatch(l -> l.startsWith("  b            50ms -> ")), check.out());
        assertTrue(!check.out().contains("player"), "no data task: " + check.out());
    }

    @Test
    void aBenchOnScaledTimeRecordsClockTicksThatRosbagsReads() throws Exception {
        Path file = dir.resolve("scaled.mcap");
        CliRun run = CliRun.of("bench", "--tasks", "1", "--period", "10ms", "--work", "0", "--duration", "2s",
                "--time-scale", "4", "--quiet", "--record", file.toString());
        assertEquals(0, run.status(), run.err());
        String checked = Ros2ProfileCheck.run(file);
        assertTrue(checked.contains("/clock ticks, each its log time, increasing"), checked);
        assertTrue(checked.contains("rosgraph_msgs/msg/Clock"), "rosbags decoded /clock: " + checked);
    }
}
