package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
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
    void parsersOfSingleLines() {
        assertEquals(Optional.empty(), HostReader.cpuMax("max 100000"), "no quota");
        assertEquals(Optional.of(2.0), HostReader.cpuMax("200000 100000"));
        assertEquals(7, HostReader.countCpuList("0-3,6,8-9"));
        assertNull(HostReader.countCpuList("0-x"));
        assertArrayEquals(new long[] {-1, -1, -1, -1}, HostReader.cpuTicks("intr 1 2\n"), "no cpu line");
        assertEquals(-1, HostReader.selfTicks("garbage"));
        assertEquals("/a/b", HostReader.cgroupV2Path("1:cpu:/x\n0::/a/b\n"));
    }
}
