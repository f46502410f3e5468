package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.core.data.Key;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MotionRequest;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Handing commits, cycles and events to the recorder allocates nothing on the calling thread. */
class RecorderAllocationTest {

    private static final Key<LaserScan> LASER = Key.of("laser", LaserScan.class, () -> new LaserScan(360));
    private static final Key<MotionRequest> MOTION = Key.of("motion", MotionRequest.class, MotionRequest::new);

    @TempDir
    Path dir;

    @Test
    void producersAllocateNothing() throws IOException {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assumeTrue(threads.isThreadAllocatedMemorySupported(), "thread allocation counting unsupported");
        RunRecorder recorder = new RunRecorder(dir.resolve("a.mcap"), List.of("t"), List.of(List.of("laser")),
                List.of(LASER, MOTION), new RecordingPlan().slots(64, 64, 64));
        LaserScan scan = new LaserScan(360);
        scan.setCount(360);
        MotionRequest motion = new MotionRequest();
        long[] generations = {1};
        long id = Thread.currentThread().getId();
        long allocated = Long.MAX_VALUE;
        for (int round = 0; round < 5; round++) {
            long before = threads.getThreadAllocatedBytes(id);
            for (int i = 0; i < 20_000; i++) {
                recorder.commit(0, i, i, scan);
                recorder.commit(1, i, i, motion);
                recorder.cycle(0, RunRecorder.MISS, i, i, i + 1, 0, generations);
                recorder.cycle(0, RunRecorder.SKIPPED, i, i, i, 2, null);
                recorder.event(RunRecorder.DEADLINE_MISS, 0, i, i, i, true, null, null);
                recorder.event(RunRecorder.EXPIRED_READ, 0, i, i, i, false, "laser", null);
                recorder.groundTruth(i, 1, 2, 3);
            }
            allocated = Math.min(allocated, threads.getThreadAllocatedBytes(id) - before);
        }
        RecordingStats stats = recorder.finish();
        assertEquals(0, allocated, "bytes allocated handing over 140 000 records (" + stats + ")");
    }
}
