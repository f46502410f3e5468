package io.rtaware.app.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.app.CliRun;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 24, finding 3: {@code --record} onto a full disk is exit 1 with the reason and what the
 * file holds, never "recording written"; an existing file is refused unless {@code --overwrite};
 * {@code --record ''} is one line.
 */
class RecordFailuresTest {

    @TempDir
    Path dir;

    private static String[] bench(Path record, String... more) {
        String[] base = {"bench", "--tasks", "3", "--period", "1ms", "--work", "0", "--duration", "2s", "--quiet",
            "--record", record.toString()};
        String[] all = new String[base.length + more.length];
        System.arraycopy(base, 0, all, 0, base.length);
        System.arraycopy(more, 0, all, base.length, more.length);
        return all;
    }

    @Test
    void anEmptyRecordNameIsOneLine() {
        CliRun.of("bench", "--tasks", "1", "--duration", "1s", "--record", "").assertOneLineUserError(
                "--record must name a file, got an empty name");
    }

    @Test
    void anExistingRecordingIsRefusedUnlessOverwriteIsGiven() throws Exception {
        Path file = dir.resolve("kept.mcap");
        Files.writeString(file, "an earlier recording");
        CliRun.of(bench(file)).assertOneLineUserError("give --overwrite to replace it");
        assertEquals("an earlier recording", Files.readString(file), "the existing file is untouched");

        CliRun replaced = CliRun.of(bench(file, "--overwrite"));
        assertEquals(0, replaced.status(), replaced.err());
        assertTrue(replaced.out().contains("recording written to " + file), replaced.out());
        assertEquals(0, CliRun.of("inspect", file.toString()).status(), "the replacement is a complete recording");
    }

    @Test
    void aFullDiskIsExitOneWithTheReasonAndWhatTheFileHolds() throws Exception {
        Path disk = Files.createDirectory(dir.resolve("small-disk"));
        Process mount = new ProcessBuilder("mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", disk.toString())
                .redirectErrorStream(true).start();
        String said = new String(mount.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assumeTrue(mount.waitFor(30, TimeUnit.SECONDS) && mount.exitValue() == 0,
                "cannot mount a 64 KiB tmpfs here (needs root): " + said.strip());
        try {
            Path file = disk.resolve("bench.mcap");
            CliRun run = CliRun.of(bench(file));
            assertEquals(1, run.status(), "a recording that could not be completed fails the command:\n" + run.err());
            assertFalse(run.out().contains("recording written"), "never called written:\n" + run.out());
            String line = run.err().lines().filter(l -> l.contains("incomplete")).findFirst().orElse("");
            assertTrue(line.contains("No space left on device"), "the reason: " + run.err());
            assertTrue(line.matches(".*it holds \\d+ messages in whole chunks \\(\\d+ bytes written.*"),
                    "how much it holds: " + line);
            assertTrue(line.contains("inspect --recover"), line);
        } finally {
            unmount(disk);
        }
    }

    /** Unmounts the test's tmpfs; lazily if it is still busy, so the temporary folder can go. */
    private static void unmount(Path disk) throws Exception {
        Process umount = new ProcessBuilder("umount", disk.toString()).redirectErrorStream(true).start();
        if (!umount.waitFor(30, TimeUnit.SECONDS) || umount.exitValue() != 0) {
            Process lazy = new ProcessBuilder("umount", "-l", disk.toString()).redirectErrorStream(true).start();
            assertTrue(lazy.waitFor(30, TimeUnit.SECONDS) && lazy.exitValue() == 0, "the test's tmpfs is unmounted");
        }
    }
}
