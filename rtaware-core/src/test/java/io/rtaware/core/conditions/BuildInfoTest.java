package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class BuildInfoTest {

    private static final String COMMIT = "0123456789abcdef0123456789abcdef01234567";

    @Test
    void headOfAPlainCheckoutFollowsItsBranch(@TempDir Path repo) throws Exception {
        Path git = Files.createDirectories(repo.resolve(".git/refs/heads"));
        Files.writeString(repo.resolve(".git/HEAD"), "ref: refs/heads/main\n");
        Files.writeString(git.resolve("main"), COMMIT + "\n");
        Path jar = Files.createDirectories(repo.resolve("rtaware-app/target")).resolve("rtaware.jar");
        assertEquals(Optional.of(COMMIT), BuildInfo.headCommit(jar));
    }

    @Test
    void headOfAWorktreeIsFoundThroughGitdirAndPackedRefs(@TempDir Path root) throws Exception {
        Path common = Files.createDirectories(root.resolve("main/.git"));
        Path wtGit = Files.createDirectories(common.resolve("worktrees/wt"));
        Files.writeString(wtGit.resolve("HEAD"), "ref: refs/heads/feature\n");
        Files.writeString(wtGit.resolve("commondir"), "../..\n");
        Files.writeString(common.resolve("packed-refs"), "# pack-refs\n" + COMMIT + " refs/heads/feature\n");
        Path wt = Files.createDirectories(root.resolve("wt"));
        Files.writeString(wt.resolve(".git"), "gitdir: " + wtGit + "\n");
        assertEquals(Optional.of(COMMIT), BuildInfo.headCommit(wt.resolve("module/target/classes")));
    }

    @Test
    void outsideACheckoutThereIsNoCommit(@TempDir Path dir) {
        assertEquals(Optional.empty(), BuildInfo.headCommit(dir));
    }

    @Test
    void concurrentCollectorBeansAreNotCountedAsPauses() {
        assertTrue(PlatformJvmProbe.countsPauses("ZGC Pauses"));
        assertTrue(PlatformJvmProbe.countsPauses("G1 Young Generation"));
        assertFalse(PlatformJvmProbe.countsPauses("ZGC Cycles"));
        assertFalse(PlatformJvmProbe.countsPauses("G1 Concurrent GC"));
    }
}
