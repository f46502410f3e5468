package io.rtaware.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.time.ManualClock;
import io.rtaware.record.RecordingListener;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RunRecorder;
import io.rtaware.record.mcap.McapReader;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.List;
import io.rtaware.core.task.TaskSpec;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Replay allocates nothing per cycle in steady state, like a run: exact replay (decoding a
 * recorded value, feeding it, running the cycle, comparing its output) and what-if replay
 * (feeding the sensor stream, running the charged cycles) of a recording twice as long allocate
 * no more on the replaying thread than of the shorter one, setup aside.
 */
class ReplayAllocationTest {

    private static final long MS = 1_000_000L;

    @TempDir
    Path dir;

    private Recording record(String name, long durationNs) throws Exception {
        Path file = dir.resolve(name);
        Monitor.Builder builder = Monitor.builder(new ManualClock());
        SyntheticReplayTest.graphOf(false, 20 * MS).forEach(builder::task);
        Monitor monitor = builder.build();
        RunRecorder recorder = RecordingListener.attach(monitor, file, new RecordingPlan());
        StepExecutor step = monitor.startStepped();
        step.runUntil(durationNs);
        monitor.stop();
        assertEquals(0, recorder.finish().dropped());
        return Recording.load(McapReader.open(file), file);
    }

    private static long allocatedReplaying(Recording recording) throws Exception {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long before = threads.getCurrentThreadAllocatedBytes();
        ExactReplay.TaskResult r = ExactReplay.replay(recording, () -> SyntheticReplayTest.graphOf(false, 20 * MS), "follower");
        long after = threads.getCurrentThreadAllocatedBytes();
        assertEquals(r.cycles(), r.identical());
        return after - before;
    }

    private static long allocatedWhatIf(Recording recording) throws Exception {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        List<TaskSpec> follower = SyntheticReplayTest.graphOf(false, 30 * MS).subList(1, 2);
        List<TaskSpec> probe = SyntheticReplayTest.graphOf(false, 30 * MS).subList(1, 2);
        long before = threads.getCurrentThreadAllocatedBytes();
        WhatIfReplay.Result r = WhatIfReplay.replay(recording, follower, probe);
        long after = threads.getCurrentThreadAllocatedBytes();
        assertEquals("sensor", r.dataTask());
        return after - before;
    }

    @Test
    void whatIfOverALongerRecordingAllocatesNothingPerCycle() throws Exception {
        Recording small = record("small.mcap", 4_000 * MS);
        Recording large = record("large.mcap", 8_000 * MS);
        for (int warm = 0; warm < 3; warm++) {
            allocatedWhatIf(small);
            allocatedWhatIf(large);
        }
        long smallBytes = allocatedWhatIf(small);
        long largeBytes = allocatedWhatIf(large);
        // 4 s more of world time: 400 more sensor values fed, 133 more follower cycles, 4000 more idle
        // cycles of the data task. Made once before the replay starts: the follower's recorded execution
        // times, 8 bytes for each of its 200 more recorded cycles; slack for lazily resolved JDK internals.
        long recordedTimes = 8 * 200;
        assertTrue(largeBytes - smallBytes < recordedTimes + 2048, "4 s more of what-if replay allocated "
                + (largeBytes - smallBytes) + " more bytes (" + smallBytes + " vs " + largeBytes + ")");
    }

    @Test
    void replayingMoreCyclesAllocatesNoMore() throws Exception {
        Recording small = record("small.mcap", 4_000 * MS);
        Recording large = record("large.mcap", 8_000 * MS);
        for (int warm = 0; warm < 3; warm++) {
            allocatedReplaying(small);
            allocatedReplaying(large);
        }
        long smallBytes = allocatedReplaying(small);
        long largeBytes = allocatedReplaying(large);
        long extraCycles = 200;
        // 200 more cycles (and 400 more commits fed); a few hundred bytes of slack for lazily resolved JDK internals.
        assertTrue(largeBytes - smallBytes < 2048, "replaying " + extraCycles + " more cycles allocated "
                + (largeBytes - smallBytes) + " more bytes (" + smallBytes + " vs " + largeBytes + ")");
    }
}
