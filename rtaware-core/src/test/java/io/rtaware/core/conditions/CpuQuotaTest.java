package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Predicate;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The cgroup files a CPU quota writes, on fixture trees laid out as cgroup v1 and v2 mount them;
 * and, where this machine lets it (root, a writable v1 or v2 CPU controller), one real quota.
 */
class CpuQuotaTest {

    @TempDir
    Path root;

    /** Does what the kernel's cgroupfs would with the fixture's plain files, and logs each operation. */
    private final List<String> log = new ArrayList<>();
    private final CpuQuota.Writes fixture = new CpuQuota.Writes() {
        @Override
        public void createDirectory(Path dir) throws IOException {
            log.add("mkdir " + root.relativize(dir));
            Files.createDirectory(dir);
        }

        @Override
        public void write(Path file, String text) throws IOException {
            log.add("write " + root.relativize(file) + " " + text);
            Files.writeString(file, text);
        }

        @Override
        public void removeDirectory(Path dir) throws IOException {
            log.add("rmdir " + root.relativize(dir));
            try (Stream<Path> files = Files.walk(dir)) {
                for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
                    Files.delete(p);
                }
            }
        }
    };

    /** The fixture's operations, except that each on a path {@code refused} names is denied, as a kernel would. */
    private CpuQuota.Writes failing(Predicate<Path> refused) {
        return new CpuQuota.Writes() {
            @Override
            public void createDirectory(Path dir) throws IOException {
                check(dir);
                fixture.createDirectory(dir);
            }

            @Override
            public void write(Path file, String text) throws IOException {
                check(file);
                fixture.write(file, text);
            }

            @Override
            public void removeDirectory(Path dir) throws IOException {
                check(dir);
                fixture.removeDirectory(dir);
            }

            private void check(Path path) throws AccessDeniedException {
                if (refused.test(path)) {
                    throw new AccessDeniedException(path.toString());
                }
            }
        };
    }

    private void v1Tree() throws IOException {
        Path cpu = Files.createDirectories(root.resolve("cpu"));
        Files.writeString(cpu.resolve("cpu.cfs_quota_us"), "-1\n");
        Files.writeString(cpu.resolve("cpu.cfs_period_us"), "100000\n");
        Files.writeString(cpu.resolve("cgroup.procs"), "1\n");
        Files.createDirectories(root.resolve("unified"));
        Files.writeString(root.resolve("unified/cgroup.controllers"), "hugetlb\n");
    }

    @Test
    void v1QuotaIsCfsQuotaOverPeriodInAChildOfTheCpuHierarchy() throws Exception {
        v1Tree();
        try (CpuQuota q = CpuQuota.create(root, "123", 0.5, fixture)) {
            assertEquals(CpuQuota.Version.V1, q.version());
            q.add(4242);
            Path group = root.resolve("cpu/rtaware-123");
            assertEquals("100000", Files.readString(group.resolve("cpu.cfs_period_us")));
            assertEquals("50000", Files.readString(group.resolve("cpu.cfs_quota_us")));
            assertEquals("4242", Files.readString(group.resolve("cgroup.procs")));
            assertEquals("0.5 CPUs (cgroup v1 cpu.cfs_quota_us 50000 per cpu.cfs_period_us 100000)", q.describe());
        }
        assertEquals(List.of("mkdir cpu/rtaware-123", "write cpu/rtaware-123/cpu.cfs_period_us 100000",
                "write cpu/rtaware-123/cpu.cfs_quota_us 50000", "write cpu/rtaware-123/cgroup.procs 4242",
                "write cpu/cgroup.procs 4242", "rmdir cpu/rtaware-123"), log,
                "closing moves the process back to the root group, then removes the group");
        assertFalse(Files.exists(root.resolve("cpu/rtaware-123")));
    }

    @Test
    void v2QuotaIsCpuMaxWithTheCpuControllerEnabledForChildren() throws Exception {
        Files.writeString(root.resolve("cgroup.controllers"), "cpuset cpu io memory pids\n");
        Files.writeString(root.resolve("cgroup.subtree_control"), "memory\n");
        try (CpuQuota q = CpuQuota.create(root, "9", 1.5, fixture)) {
            assertEquals(CpuQuota.Version.V2, q.version());
            assertEquals("150000 100000", Files.readString(root.resolve("rtaware-9/cpu.max")));
            assertEquals("1.5 CPUs (cgroup v2 cpu.max 150000 100000)", q.describe());
        }
        assertEquals(List.of("write cgroup.subtree_control +cpu", "mkdir rtaware-9", "write rtaware-9/cpu.max 150000 100000",
                "rmdir rtaware-9"), log);
    }

    @Test
    void withNeitherControllerTheRefusalIsOneLineNamingWhatWasLookedFor() throws Exception {
        Files.createDirectories(root.resolve("unified"));
        Files.writeString(root.resolve("cgroup.controllers"), "memory pids\n");
        CpuQuota.Unavailable e = assertThrows(CpuQuota.Unavailable.class, () -> CpuQuota.create(root, "1", 1, fixture));
        assertEquals("--cpu-limit needs a CPU controller: neither cgroup v2 (" + root.resolve("cgroup.controllers")
                + " lists no 'cpu') nor cgroup v1 (no " + root.resolve("cpu/cpu.cfs_quota_us") + ") is there", e.getMessage());
        assertTrue(log.isEmpty());
    }

    @Test
    void anUnwritableHierarchyIsRefusedInOneLineAndLeavesNothing() throws Exception {
        v1Tree();
        CpuQuota.Writes readOnly = failing(p -> true);
        CpuQuota.Unavailable e = assertThrows(CpuQuota.Unavailable.class, () -> CpuQuota.create(root, "5", 1, readOnly));
        Path group = root.resolve("cpu/rtaware-5");
        assertEquals("--cpu-limit: cannot create the cgroup " + group + " (AccessDeniedException: " + group
                + "); it needs root or a delegated cgroup v1 hierarchy", e.getMessage());
        assertFalse(e.getMessage().contains("\n"));
        assertFalse(Files.exists(group));
    }

    @Test
    void aQuotaTheKernelRefusesRemovesTheGroupItMade() throws Exception {
        v1Tree();
        CpuQuota.Writes refusesQuota = failing(p -> p.endsWith("cpu.cfs_quota_us"));
        CpuQuota.Unavailable e = assertThrows(CpuQuota.Unavailable.class, () -> CpuQuota.create(root, "6", 2, refusesQuota));
        assertTrue(e.getMessage().startsWith("--cpu-limit: cannot set the quota of "), e.getMessage());
        assertFalse(Files.exists(root.resolve("cpu/rtaware-6")));
    }

    @Test
    void theQuotaMustBeWhatTheKernelTakes() {
        assertEquals("must be a number of CPUs from 0.01 to 1024, got 0.001", CpuQuota.invalid(0.001));
        assertEquals("must be a number of CPUs from 0.01 to 1024, got NaN", CpuQuota.invalid(Double.NaN));
        assertEquals(null, CpuQuota.invalid(0.01));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CpuQuota.create(root, "1", 0, fixture));
        assertEquals("--cpu-limit must be a number of CPUs from 0.01 to 1024, got 0.0", e.getMessage());
    }

    /**
     * On this machine: a real group, a real process moved into it, the quota the kernel holds for it,
     * and the process's own {@code /proc/PID/cgroup} naming the group; then nothing left behind.
     */
    @Test
    @Requires(WritableCpuController.class)
    void aRealProcessIsPlacedUnderARealQuotaAndTheGroupIsRemoved() throws Exception {
        Process sleeper = new ProcessBuilder("sleep", "600").start();
        Path group;
        try (CpuQuota q = CpuQuota.create(CpuQuota.SYSTEM_ROOT, "test-" + ProcessHandle.current().pid(), 0.25,
                CpuQuota.SYSTEM)) {
            group = q.group();
            q.add(sleeper.pid());
            String quotaFile = q.version() == CpuQuota.Version.V2 ? "cpu.max" : "cpu.cfs_quota_us";
            assertEquals(q.version() == CpuQuota.Version.V2 ? "25000 100000" : "25000",
                    Files.readString(group.resolve(quotaFile)).strip());
            String own = Files.readString(Path.of("/proc", Long.toString(sleeper.pid()), "cgroup"));
            assertTrue(own.contains("/" + group.getFileName()), own);
            HostFiles proc = new HostFiles(Path.of("/"));
            assertTrue(proc.read(group.resolve("cgroup.procs").toString()).orElse("").contains(Long.toString(sleeper.pid())));
        } finally {
            sleeper.destroyForcibly().waitFor();
        }
        assertFalse(Files.exists(group), "the group is removed");
    }
}
