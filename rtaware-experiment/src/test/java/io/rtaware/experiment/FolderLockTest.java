package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** One experiment per folder: refused while the owner lives, taken over when it is dead. */
class FolderLockTest {

    @TempDir
    Path dir;

    @Test
    void aSecondLockOnTheSameFolderIsRefusedUntilTheFirstIsReleased() throws Exception {
        long own = ProcessHandle.current().pid();
        try (FolderLock first = FolderLock.acquire(dir)) {
            assertEquals(own + "\n", Files.readString(first.file()), "the lock file holds the owner's pid");
            ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> FolderLock.acquire(dir));
            assertTrue(e.getMessage().contains("in use by another rtaware experiment (pid " + own + ")"), e.getMessage());
        }
        assertFalse(Files.exists(dir.resolve(FolderLock.FILE_NAME)), "released and deleted");
        FolderLock.acquire(dir).close();
    }

    @Test
    void aLockFileOfALiveProcessIsRefused() throws Exception {
        Process owner = new ProcessBuilder("sleep", "60").start();
        try {
            Files.writeString(dir.resolve(FolderLock.FILE_NAME), owner.pid() + "\n");
            ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> FolderLock.acquire(dir));
            assertTrue(e.getMessage().contains("(pid " + owner.pid() + ", "), e.getMessage());
            assertEquals(owner.pid() + "\n", Files.readString(dir.resolve(FolderLock.FILE_NAME)), "left as it was");
        } finally {
            owner.destroyForcibly().waitFor();
        }
    }

    @Test
    void aLockFileOfADeadProcessIsTakenOver() throws Exception {
        Process gone = new ProcessBuilder("true").start();
        gone.waitFor();
        Files.writeString(dir.resolve(FolderLock.FILE_NAME), gone.pid() + "\n");
        try (FolderLock lock = FolderLock.acquire(dir)) {
            assertEquals(ProcessHandle.current().pid() + "\n", Files.readString(lock.file()));
        }
    }

    @Test
    void theLivenessTestDecides() throws Exception {
        Files.writeString(dir.resolve(FolderLock.FILE_NAME), "4242\n");
        assertThrows(ExperimentInputException.class, () -> FolderLock.acquire(dir, 1, pid -> pid == 4242));
        FolderLock.acquire(dir, 1, pid -> false).close();
    }
}
