package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class HostReaderTest {

    static Path fixture(String name) {
        try {
            return Path.of(HostReaderTest.class.getResource("/conditions/" + name).toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Copies a fixture machine over the folder (the state of /proc at that moment). */
    static void lay(String fixture, Path root) throws IOException {
        Path from = fixture(fixture);
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                Path to = root.resolve(from.relativize(f).toString());
                Files.createDirectories(to.getParent());
                Files.copy(f, to, StandardCopyOption.REPLACE_EXISTING);
            }
        }
    }

    private static HostReader reader(String name) {
        return new HostReader(new HostFiles(fixture(name)), () -> 0);
    }

    @Test
    void readsTheMachineFromFixtureProcAndSysFiles() {
        HostReader host = reader("busy-start");
        assertEquals("AMD EPYC 7B13", host.cpuModel(), "model name of /proc/cpuinfo");
        assertEquals(2, host.logicalCpus(), "cpuN lines of /proc/stat");
        assertEquals(2, host.affinityCpus(), "Cpus_allowed_list 0-1");
        assertEquals(1.5, host.cgroupQuotaCpus(), 1e-12, "cpu.max 150000 100000 of the process's cgroup");
        assertEquals(1.5, host.usableCpus(), 1e-12, "the quota is the tightest limit");
        assertEquals("6.1.0-13-amd64", host.kernel());
        assertEquals(Boolean.TRUE, host.virtualized(), "the 'hypervisor' CPU flag");
        assertEquals("QEMU Standard PC (Q35 + ICH9, 2009)", host.hypervisor(), "DMI vendor and product");
        assertEquals("kvm-clock", host.clockSource());
    }

    @Test
    void samplesTheCountersOfMachineAndProcess() {
        HostSample s = reader("busy-start").sample();
        assertEquals(14.2, s.load1(), 1e-12);
        assertEquals(2, s.cpus());
        assertEquals(62_600, s.totalTicks(), "sum of user..steal of the cpu line");
        assertEquals(12_000, s.busyTicks(), "user + nice + system + irq + softirq");
        assertEquals(100, s.stealTicks());
        assertEquals(400, s.selfTicks(), "utime 300 + stime 100, after a command name holding spaces and parentheses");
        assertEquals(10, s.involuntarySwitches(), "summed over the threads in /proc/self/task");
        assertEquals(Map.of(1L, 110L, 2L, 3L, 100L, 1000L, 200L, 10L, 300L, 40L), s.otherTicks(),
                "every process but this one (4242), utime + stime + cutime + cstime, kernel threads too");
    }

    /** The third red team hid load in a process whose name holds a newline: its counters are on the second line. */
    @Test
    void aProcessWhoseNameHoldsANewlineIsCounted(@TempDir Path root) throws Exception {
        lay("busy-start", root);
        Files.writeString(root.resolve("proc/300/stat"),
                "300 (hide\nme) R 1 300 300 0 -1 4194304 100 0 0 0 30 10 0 0 20 0 1 0 100 1000 10 0 0\n");
        assertEquals(40L, new HostReader(new HostFiles(root), () -> 0).sample().otherTicks().get(300L),
                "utime 30 + stime 10 after the name's newline");
    }

    @Test
    void aProcMountThatHidesOtherUsersProcessesGivesNoProcessTable(@TempDir Path root) throws Exception {
        lay("busy-start", root);
        Files.writeString(root.resolve("proc/mounts"), "proc /proc proc rw,nosuid,nodev,noexec,relatime,hidepid=invisible 0 0\n");
        assertNull(new HostReader(new HostFiles(root), () -> 0).sample().otherTicks(),
                "with hidepid only this user's processes are listed: the table would miss the others");
        Files.writeString(root.resolve("proc/mounts"), "proc /proc proc rw,relatime,hidepid=0 0 0\n");
        assertEquals(5, new HostReader(new HostFiles(root), () -> 0).sample().otherTicks().size(), "hidepid=0 hides nothing");
    }

    @Test
    void aProcessTableWithoutThisProcessIsNotTrusted(@TempDir Path root) throws Exception {
        lay("busy-start", root);
        try (var files = Files.walk(root.resolve("proc/4242"))) {
            files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
        assertNull(new HostReader(new HostFiles(root), () -> 0).sample().otherTicks(),
                "a /proc that does not list this process is not this machine's process table");
    }


    @Test
    void aMachineWithoutTheFilesIsUnknownNotAnError(@TempDir Path empty) {
        HostReader host = new HostReader(new HostFiles(empty), () -> 0);
        assertEquals("unknown", host.cpuModel());
        assertEquals(-1, host.logicalCpus());
        assertNull(host.affinityCpus());
        assertNull(host.cgroupQuotaCpus());
        assertNull(host.virtualized());
        assertNull(host.hypervisor());
        HostSample s = host.sample();
        assertEquals(-1, s.totalTicks());
        assertEquals(-1, s.selfTicks());
        assertEquals(-1, s.involuntarySwitches());
        assertTrue(Double.isNaN(s.load1()));
    }

    @Test
    void cgroupV1QuotaIsReadWhenThereIsNoV2Limit(@TempDir Path root) throws Exception {
        Path v1 = Files.createDirectories(root.resolve("sys/fs/cgroup/cpu"));
        Files.writeString(v1.resolve("cpu.cfs_quota_us"), "50000\n");
        Files.writeString(v1.resolve("cpu.cfs_period_us"), "100000\n");
        assertEquals(0.5, new HostReader(new HostFiles(root), () -> 0).cgroupQuotaCpus(), 1e-12);
    }

    @Test
    void cgroupV1QuotaIsThatOfTheProcesssOwnGroup(@TempDir Path root) throws Exception {
        Path v1 = Files.createDirectories(root.resolve("sys/fs/cgroup/cpu"));
        Files.writeString(v1.resolve("cpu.cfs_quota_us"), "-1\n");
        Files.writeString(v1.resolve("cpu.cfs_period_us"), "100000\n");
        Path own = Files.createDirectories(v1.resolve("rtaware-77"));
        Files.writeString(own.resolve("cpu.cfs_quota_us"), "25000\n");
        Files.writeString(own.resolve("cpu.cfs_period_us"), "100000\n");
        Files.createDirectories(root.resolve("proc/self"));
        Files.writeString(root.resolve("proc/self/cgroup"), "4:memory:/x\n1:cpu,cpuacct:/rtaware-77\n0::/\n");
        assertEquals(0.25, new HostReader(new HostFiles(root), () -> 0).cgroupQuotaCpus(), 1e-12,
                "the quota of /rtaware-77, not the hierarchy root's none");
        Files.writeString(root.resolve("proc/self/cgroup"), "1:cpu,cpuacct:/docker/abc\n0::/\n");
        assertNull(new HostReader(new HostFiles(root), () -> 0).cgroupQuotaCpus(),
                "a group not visible here: the root's, which has none");
    }

    @Test
    void parsersOfSingleLines() {
        assertEquals(Optional.empty(), HostReader.cpuMax("max 100000"), "no quota");
        assertEquals(Optional.of(2.0), HostReader.cpuMax("200000 100000"));
        assertEquals(7, HostReader.countCpuList("0-3,6,8-9"));
        assertNull(HostReader.countCpuList("0-x"));
        assertArrayEquals(new long[] {-1, -1, -1, -1}, HostReader.cpuTicks("intr 1 2\n"), "no cpu line");
        assertEquals(-1, HostReader.selfTicks("garbage"));
        assertEquals(4 + 5 + 6 + 7, HostReader.processTicks("9 (a) b) c) S 1 9 9 0 -1 0 0 0 0 0 4 5 6 7 20 0 1 0"),
                "utime stime cutime cstime after a name with spaces and parentheses");
        assertEquals(-1, HostReader.processTicks("9 (a) S 1 9"), "too short");
        assertEquals(-1, HostReader.processTicks("9 (a) S 1 9 9 0 -1 0 0 0 0 0 4 -5 6 7"), "negative");
        assertEquals(4242, HostReader.pid("4242 (java) S 1"));
        assertEquals(-1, HostReader.pid("x (java) S 1"));
        assertTrue(HostReader.procHidesPids("sysfs /sys sysfs rw 0 0\nproc /proc proc rw,hidepid=2 0 0\n"));
        assertFalse(HostReader.procHidesPids("proc /proc proc rw,relatime 0 0\nproc /mnt proc rw,hidepid=2 0 0\n"),
                "only the proc at /proc counts");
        assertEquals("/a/b", HostReader.cgroupV2Path("1:cpu:/x\n0::/a/b\n"));
    }

    @Test
    void readsTheShareOfResidentMemoryInHugePagesFromSmapsRollup() {
        assertEquals(100.0 * (12_288 + 524_288) / 633_868, reader("busy-end").sample().hugePagesPct(), 1e-9,
                "transparent huge pages of anonymous memory and of ZGC's shared-memory heap, of the resident memory");
        assertTrue(Double.isNaN(reader("busy-start").sample().hugePagesPct()), "no smaps_rollup: not known");
        assertEquals(0.0, HostReader.hugePagesPct("Rss:  1728 kB\nAnonHugePages:  0 kB\nShmemPmdMapped:  0 kB\n"),
                "read, none");
        assertEquals(50.0, HostReader.hugePagesPct("Rss:  8192 kB\nPrivate_Hugetlb:  4096 kB\n"),
                "explicit huge pages count");
        assertTrue(Double.isNaN(HostReader.hugePagesPct("Rss:  1728 kB\n")), "none of the huge page lines: not known");
        assertTrue(Double.isNaN(HostReader.hugePagesPct("AnonHugePages:  0 kB\n")), "no resident size: not known");
    }
}
