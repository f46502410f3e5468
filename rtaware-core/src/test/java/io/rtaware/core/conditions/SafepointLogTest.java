package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The JVM's safepoint log: its lines as JDK 17 and JDK 25 write them, and this JVM's own. */
class SafepointLogTest {

    @Test
    void readsJdk17Lines() {
        SafepointLog.Safepoint s = SafepointLog.parse("[1297604845ns] Safepoint \"ZMarkStart\", Time since last: 55516387 ns,"
                + " Reaching safepoint: 100098 ns, Cleanup: 34071 ns, At safepoint: 11887 ns, Total: 146056 ns");
        assertEquals(new SafepointLog.Safepoint("ZMarkStart", 100_098, 11_887, 146_056), s);
        assertTrue(s.collectorPause());
    }

    @Test
    void readsJdk25Lines() {
        SafepointLog.Safepoint s = SafepointLog.parse("[2059708010ns] Safepoint \"ZMarkStartYoung\", Time since last:"
                + " 1595669258 ns, Reaching safepoint: 5718 ns, At safepoint: 20420 ns, Leaving safepoint: 932 ns,"
                + " Total: 27070 ns, Threads: 0 runnable, 10 total");
        assertEquals(new SafepointLog.Safepoint("ZMarkStartYoung", 5_718, 20_420, 27_070), s);
        assertTrue(s.collectorPause());
    }

    @Test
    void tellsTheCollectorsPausesFromOtherSafepoints() {
        for (String collector : List.of("G1CollectForAllocation", "G1PauseRemark", "ParallelGCFailedAllocation",
                "GenCollectForAllocation", "SerialCollectForAllocation", "ZRelocateStart", "ShenandoahInitMark",
                "CollectForMetadataAllocation")) {
            assertTrue(new SafepointLog.Safepoint(collector, 0, 0, 0).collectorPause(), collector);
        }
        for (String other : List.of("Cleanup", "ICBufferFull", "HandshakeAllThreads", "CleanClassLoaderDataMetaspaces",
                "Deoptimize", "ThreadDump", "FindDeadlocks")) {
            assertFalse(new SafepointLog.Safepoint(other, 0, 0, 0).collectorPause(), other);
        }
    }

    @Test
    void otherLinesAreNotSafepoints() {
        assertNull(SafepointLog.parse("[123ns] Entering safepoint region: ZMarkStart"));
        assertNull(SafepointLog.parse(""));
    }

    /** Switched on, a full collection's safepoint is logged; switched off, the file holds it and no more. */
    @Test
    void thisJvmLogsItsSafepointsWhileSwitchedOn(@TempDir Path dir) throws IOException {
        Path file = Files.createFile(dir.resolve("safepoints.log"));
        SafepointLog log = SafepointLog.start(file);
        System.gc(); // every collector stops the threads for an explicit full collection
        List<SafepointLog.Safepoint> safepoints = log.stop();

        assertTrue(safepoints.stream().anyMatch(SafepointLog.Safepoint::collectorPause),
                "the collection's safepoint: " + safepoints);
        long linesAtStop = Files.readAllLines(file).size();
        System.gc();
        assertEquals(linesAtStop, Files.readAllLines(file).size(), "nothing written once switched off");
    }

    @Test
    void refusesAPathVmLogCannotTake(@TempDir Path dir) throws IOException {
        Path file = Files.createFile(dir.resolve("a,b.log"));
        IOException e = org.junit.jupiter.api.Assertions.assertThrows(IOException.class, () -> SafepointLog.start(file));
        assertTrue(e.getMessage().contains("a,b.log"), e.getMessage());
    }
}
