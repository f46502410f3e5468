package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.testing.LiveThreads;
import io.rtaware.core.testing.ThreadAllocation;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The recorder's writer thread as the allocation check sees it. */
class RecorderWriterThreadTest {

    /**
     * The writer encodes and writes what the task threads handed over, off their path: the
     * allocation check of {@code bench --record --fail-on-alloc} does not count it as the
     * framework's on the per-release path.
     */
    @Test
    void theWriterIsOffTheTasksPerReleasePath() {
        Set<Thread> before = Set.of(LiveThreads.all());
        RecorderWriterThread writer = new RecorderWriterThread(List.of(),
                (channel, sequence, logTimeNs, publishTimeNs, data, offset, length) -> { });
        writer.start();
        try {
            List<Thread> started = Arrays.stream(LiveThreads.all()).filter(t -> !before.contains(t)).toList();
            assertEquals(1, started.stream().filter(t -> t.getName().startsWith(ThreadNames.PREFIX)).count(),
                    "the writer is a thread of rtaware's: " + started);
            assertEquals(List.of(), started.stream().filter(ThreadAllocation::onReleasePath).toList(),
                    "counted as the framework's on the per-release path");
        } finally {
            assertNull(writer.stopAndJoin(), "nothing failed");
        }
    }
}
