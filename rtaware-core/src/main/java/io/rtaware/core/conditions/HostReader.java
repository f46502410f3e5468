package io.rtaware.core.conditions;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.function.LongSupplier;

/**
 * Reads the machine from its {@code /proc} and {@code /sys} files: what does not change during a
 * run (CPU model, CPUs, affinity and cgroup quota, kernel, hypervisor, clock source) and the
 * counters of a {@link HostSample}. Each parser is a pure function of a file's text, tested on
 * fixture files. Linux files; elsewhere every value is unknown. Thread-safe.
 */
public final class HostReader {

    private final HostFiles files;
    private final LongSupplier nanoTime;

    /**
     * @param files the machine's files
     * @param nanoTime the clock of the samples, e.g. {@code System::nanoTime}
     */
    public HostReader(HostFiles files, LongSupplier nanoTime) {
        this.files = Objects.requireNonNull(files, "files");
        this.nanoTime = Objects.requireNonNull(nanoTime, "nanoTime");
    }

    /** @return the counters now */
    public HostSample sample() {
        long now = nanoTime.getAsLong();
        double load = files.firstLine("/proc/loadavg").map(HostReader::load1).orElse(Double.NaN);
        long[] cpu = files.read("/proc/stat").map(HostReader::cpuTicks).orElse(new long[] {-1, -1, -1, -1});
        // The whole file, not its first line: a command name may hold a newline.
        Optional<String> selfStat = files.read("/proc/self/stat");
        long self = selfStat.map(HostReader::selfTicks).orElse(-1L);
        Map<Long, Long> others = selfStat.map(HostReader::pid).filter(pid -> pid > 0).map(this::otherTicks).orElse(null);
        return new HostSample(now, load, (int) cpu[3], cpu[0], cpu[1], cpu[2], self, involuntarySwitches(), others,
                hugePagesPct());
    }

    /**
     * The share of this process's resident memory mapped in huge pages ({@code
     * /proc/self/smaps_rollup}: transparent huge pages of anonymous memory, of shared memory such
     * as ZGC's heap and of files, and explicit ones from {@code hugetlbfs}). A drain of thousands
     * of tasks reads each task's objects once a period, one 4 KiB page after another, and ran
     * 15-20 % faster with the heap in 2 MiB pages (docs/performance.md), most likely because the
     * processor's address translations then hit its TLB instead of walking the page tables, two
     * walks on a virtual machine.
     *
     * @return percent, or NaN where the file cannot be read
     */
    private double hugePagesPct() {
        return files.read("/proc/self/smaps_rollup").map(HostReader::hugePagesPct).orElse(Double.NaN);
    }

    /**
     * The file sums each figure over the process's mappings, so memory mapped at several addresses
     * counts once per mapping in both parts of the share (JDK 17's ZGC maps its heap three times:
     * 512 MiB of heap in huge pages reads as 1536 MiB of {@code ShmemPmdMapped}); the share is
     * still the share.
     *
     * @param smapsRollup the text of {@code /proc/PID/smaps_rollup}
     * @return the sum of its {@code AnonHugePages}, {@code ShmemPmdMapped}, {@code FilePmdMapped},
     *     {@code Shared_Hugetlb} and {@code Private_Hugetlb} lines (a line the kernel does not
     *     write counts nothing) as a percentage of its {@code Rss} line, at most 100; NaN without
     *     an {@code Rss} above 0 or without any of those lines
     */
    static double hugePagesPct(String smapsRollup) {
        long rss = kibField(smapsRollup, "Rss");
        long huge = 0;
        boolean any = false;
        for (String key : new String[] {"AnonHugePages", "ShmemPmdMapped", "FilePmdMapped", "Shared_Hugetlb",
                "Private_Hugetlb"}) {
            long kb = kibField(smapsRollup, key);
            if (kb >= 0) {
                huge += kb;
                any = true;
            }
        }
        return rss > 0 && any ? Math.min(100.0, 100.0 * huge / rss) : Double.NaN;
    }

    /** @return a {@code key: N kB} line's N, or -1 if there is no such line or it is not a count */
    private static long kibField(String text, String key) {
        return field(text, key).map(v -> v.endsWith("kB") ? v.substring(0, v.length() - 2) : v)
                .map(HostReader::parseLongOrMinus).orElse(-1L);
    }

    /**
     * Every other process's and kernel thread's CPU time by its own counters ({@code /proc/PID/stat}:
     * utime + stime + cutime + cstime). These are the same precise accounting as this process's
     * own, where {@code /proc/stat}'s busy time is sampled at the timer tick: on the 2-vCPU
     * development VM, with nothing else running, the machine's busy time minus this process's
     * came out between -2.9 and +2.4 CPU-seconds over three 24 s paper-course runs (-0.12 to +0.10
     * CPUs), while all other processes' own counters summed to 0.35-0.40 CPU-seconds.
     *
     * @param selfPid this process's id, left out
     * @return ticks per process id, or null when {@code /proc} hides other users' processes
     *     ({@code hidepid}) or does not list this process
     */
    private Map<Long, Long> otherTicks(long selfPid) {
        boolean hidden = files.read("/proc/mounts").map(HostReader::procHidesPids).orElse(false);
        if (hidden) {
            return null;
        }
        Map<Long, Long> ticks = new HashMap<>();
        boolean sawSelf = false;
        for (String name : files.list("/proc")) {
            long pid = parsePid(name);
            if (pid < 0) {
                continue;
            }
            if (pid == selfPid) {
                sawSelf = true;
                continue;
            }
            // The whole file: a name with a newline puts the counters on a later line.
            long t = files.read("/proc/" + name + "/stat").map(HostReader::processTicks).orElse(-1L);
            if (t >= 0) {
                ticks.put(pid, t); // a process that ended between the listing and the read is left out
            }
        }
        return sawSelf ? ticks : null;
    }

    private static long parsePid(String name) {
        if (name.isEmpty() || name.length() > 18) {
            return -1;
        }
        for (int i = 0; i < name.length(); i++) {
            if (!Character.isDigit(name.charAt(i))) {
                return -1;
            }
        }
        return Long.parseLong(name);
    }

    /**
     * @param mounts the text of {@code /proc/mounts}
     * @return whether the {@code proc} file system at {@code /proc} hides other users' processes
     */
    static boolean procHidesPids(String mounts) {
        for (String line : mounts.lines().toList()) {
            String[] f = line.strip().split("\\s+");
            if (f.length >= 4 && f[1].equals("/proc") && f[2].equals("proc")) {
                for (String option : f[3].split(",")) {
                    if (option.startsWith("hidepid=") && !option.equals("hidepid=0") && !option.equals("hidepid=off")) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /** @return the CPU's model name, or {@code unknown} */
    public String cpuModel() {
        return files.read("/proc/cpuinfo").flatMap(HostReader::cpuModel).orElse("unknown");
    }

    /** @return the CPUs the OS counts ({@code cpuN} lines of {@code /proc/stat}), or -1 */
    public int logicalCpus() {
        return files.read("/proc/stat").map(t -> (int) cpuTicks(t)[3]).orElse(-1);
    }

    /** @return the CPUs this process may run on ({@code Cpus_allowed_list}), or null if unknown */
    public Integer affinityCpus() {
        return files.read("/proc/self/status").flatMap(t -> field(t, "Cpus_allowed_list"))
                .map(HostReader::countCpuList).orElse(null);
    }

    /**
     * @return the CPU quota of this process's cgroup in CPUs (v2 {@code cpu.max}, or v1
     *     {@code cpu.cfs_quota_us / cpu.cfs_period_us}), or null when there is none
     */
    public Double cgroupQuotaCpus() {
        String group = files.read("/proc/self/cgroup").map(HostReader::cgroupV2Path).orElse(null);
        if (group != null) {
            String base = "/sys/fs/cgroup" + (group.equals("/") ? "" : group);
            Optional<Double> quota = files.firstLine(base + "/cpu.max").flatMap(HostReader::cpuMax);
            if (quota.isPresent()) {
                return quota.get();
            }
        }
        // v1: this process's group in the cpu hierarchy (where CpuQuota puts it), else the
        // hierarchy's root (a container sees its own group there, under a path it cannot see).
        String v1 = files.read("/proc/self/cgroup").map(HostReader::cgroupV1CpuPath).orElse(null);
        String base = "/sys/fs/cgroup/cpu";
        if (v1 != null && !v1.equals("/") && files.firstLine(base + v1 + "/cpu.cfs_quota_us").isPresent()) {
            base = base + v1;
        }
        Optional<String> quotaUs = files.firstLine(base + "/cpu.cfs_quota_us");
        Optional<String> periodUs = files.firstLine(base + "/cpu.cfs_period_us");
        if (quotaUs.isPresent() && periodUs.isPresent()) {
            try {
                long q = Long.parseLong(quotaUs.get());
                long p = Long.parseLong(periodUs.get());
                return q > 0 && p > 0 ? (double) q / p : null;
            } catch (NumberFormatException e) {
                return null;
            }
        }
        return null;
    }

    /** @return the kernel's release ({@code /proc/sys/kernel/osrelease}), or the JVM's {@code os.version} */
    public String kernel() {
        return files.firstLine("/proc/sys/kernel/osrelease")
                .orElse(System.getProperty("os.name") + " " + System.getProperty("os.version"));
    }

    /** @return true if the CPU flags say {@code hypervisor}, false if they do not, null without {@code /proc/cpuinfo} */
    public Boolean virtualized() {
        return files.read("/proc/cpuinfo").map(t -> t.lines().filter(l -> l.startsWith("flags"))
                .anyMatch(l -> (" " + l.substring(l.indexOf(':') + 1) + " ").contains(" hypervisor "))).orElse(null);
    }

    /**
     * @return the hypervisor where the kernel names it ({@code /sys/hypervisor/type}, else the
     *     DMI vendor and product), or null
     */
    public String hypervisor() {
        Optional<String> type = files.firstLine("/sys/hypervisor/type");
        if (type.isPresent()) {
            return type.get();
        }
        String vendor = files.firstLine("/sys/class/dmi/id/sys_vendor").orElse("");
        String product = files.firstLine("/sys/class/dmi/id/product_name").orElse("");
        String both = (vendor + " " + product).strip();
        return both.isEmpty() ? null : both;
    }

    /** @return the kernel's clock source, e.g. {@code tsc}, or {@code unknown} */
    public String clockSource() {
        return files.firstLine("/sys/devices/system/clocksource/clocksource0/current_clocksource").orElse("unknown");
    }

    private long involuntarySwitches() {
        List<String> threads = files.list("/proc/self/task");
        if (threads.isEmpty()) {
            return files.read("/proc/self/status").flatMap(t -> field(t, "nonvoluntary_ctxt_switches"))
                    .map(HostReader::parseLongOrMinus).orElse(-1L);
        }
        long sum = 0;
        boolean any = false;
        for (String tid : threads) {
            Optional<Long> n = files.read("/proc/self/task/" + tid + "/status")
                    .flatMap(t -> field(t, "nonvoluntary_ctxt_switches")).map(HostReader::parseLongOrMinus)
                    .filter(v -> v >= 0);
            if (n.isPresent()) {
                sum += n.get();
                any = true;
            }
        }
        return any ? sum : -1;
    }

    // ------------------------------------------------------------------ parsers of one file's text

    /**
     * @param loadavg the first line of {@code /proc/loadavg}
     * @return its one-minute load average, or NaN
     */
    static double load1(String loadavg) {
        String[] parts = loadavg.strip().split("\\s+");
        try {
            return Double.parseDouble(parts[0]);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /**
     * @param stat the text of {@code /proc/stat}
     * @return {total, busy, steal, cpu count} in clock ticks from its {@code cpu} line (busy is
     *     user + nice + system + irq + softirq), -1 where unknown
     */
    static long[] cpuTicks(String stat) {
        long[] out = {-1, -1, -1, -1};
        int cpus = 0;
        for (String line : stat.lines().toList()) {
            String[] f = line.strip().split("\\s+");
            if (f[0].equals("cpu") && f.length >= 5) {
                long[] v = new long[Math.min(f.length - 1, 8)];
                try {
                    for (int i = 0; i < v.length; i++) {
                        v[i] = Long.parseLong(f[i + 1]);
                    }
                } catch (NumberFormatException e) {
                    continue;
                }
                long total = 0;
                for (long x : v) {
                    total += x; // user nice system idle iowait irq softirq steal (guest is inside user)
                }
                long idle = v[3] + (v.length > 4 ? v[4] : 0);
                long steal = v.length > 7 ? v[7] : 0;
                out[0] = total;
                out[1] = total - idle - steal;
                out[2] = steal;
            } else if (f[0].startsWith("cpu") && f[0].length() > 3 && Character.isDigit(f[0].charAt(3))) {
                cpus++;
            }
        }
        out[3] = cpus == 0 ? -1 : cpus;
        return out;
    }

    /**
     * @param stat the line of {@code /proc/self/stat}
     * @return utime + stime in clock ticks (fields 14 and 15), or -1
     */
    static long selfTicks(String stat) {
        return statTicks(stat, 14, 15);
    }

    /**
     * @param stat the line of {@code /proc/PID/stat}
     * @return its process id (field 1), or -1
     */
    static long pid(String stat) {
        int space = stat.indexOf(' ');
        return space <= 0 ? -1 : parsePid(stat.substring(0, space));
    }

    /**
     * @param stat the line of {@code /proc/PID/stat}
     * @return utime + stime + cutime + cstime in clock ticks (fields 14 to 17: the process's own
     *     CPU time and that of the children it has reaped), or -1
     */
    static long processTicks(String stat) {
        return statTicks(stat, 14, 17);
    }

    /**
     * @param stat a line of {@code /proc/PID/stat}
     * @param first the first field summed, numbered as in proc(5) (1 is the process id)
     * @param last the last field summed
     * @return the sum of those fields, counted after the command name in parentheses (which may
     *     hold spaces and parentheses), or -1 if one is missing, not a number or negative
     */
    private static long statTicks(String stat, int first, int last) {
        int close = stat.lastIndexOf(')');
        if (close < 0) {
            return -1;
        }
        String[] f = stat.substring(close + 1).strip().split("\\s+"); // f[0] is field 3 (state)
        if (f.length < last - 2) {
            return -1;
        }
        try {
            long sum = 0;
            for (int field = first; field <= last; field++) {
                long v = Long.parseLong(f[field - 3]);
                if (v < 0) {
                    return -1;
                }
                sum += v;
            }
            return sum;
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    /**
     * @param cpuinfo the text of {@code /proc/cpuinfo}
     * @return the first {@code model name} (x86) or {@code Model}/{@code Hardware} (ARM) value
     */
    static Optional<String> cpuModel(String cpuinfo) {
        for (String key : List.of("model name", "Model", "Hardware", "cpu model")) {
            Optional<String> v = field(cpuinfo, key);
            if (v.isPresent() && !v.get().isEmpty()) {
                return v;
            }
        }
        return Optional.empty();
    }

    /**
     * @param list a CPU list such as {@code 0-3,6,8-9}
     * @return how many CPUs it names, or null if it does not parse
     */
    static Integer countCpuList(String list) {
        int n = 0;
        try {
            for (String part : list.strip().split(",")) {
                if (part.isBlank()) {
                    continue;
                }
                int dash = part.indexOf('-');
                n += dash < 0 ? 1 : Integer.parseInt(part.substring(dash + 1).strip())
                        - Integer.parseInt(part.substring(0, dash).strip()) + 1;
            }
        } catch (NumberFormatException e) {
            return null;
        }
        return n;
    }

    /**
     * @param cgroup the text of {@code /proc/self/cgroup}
     * @return the path of this process's group in the v1 hierarchy whose controllers include
     *     {@code cpu} (a line {@code N:cpu,cpuacct:PATH}), or null
     */
    static String cgroupV1CpuPath(String cgroup) {
        for (String line : cgroup.lines().toList()) {
            String[] f = line.split(":", 3);
            if (f.length == 3 && List.of(f[1].split(",")).contains("cpu")) {
                return f[2].strip();
            }
        }
        return null;
    }

    /**
     * @param cgroup the text of {@code /proc/self/cgroup}
     * @return the path of this process's group in the unified (v2) hierarchy, or null
     */
    static String cgroupV2Path(String cgroup) {
        return cgroup.lines().filter(l -> l.startsWith("0::")).map(l -> l.substring(3).strip()).findFirst().orElse(null);
    }

    /**
     * @param cpuMax the line of a cgroup v2 {@code cpu.max}: {@code QUOTA PERIOD} or {@code max PERIOD}
     * @return the quota in CPUs, empty for {@code max} (no quota)
     */
    static Optional<Double> cpuMax(String cpuMax) {
        String[] f = cpuMax.strip().split("\\s+");
        if (f.length < 2 || f[0].equals("max")) {
            return Optional.empty();
        }
        try {
            double quota = Double.parseDouble(f[0]);
            double period = Double.parseDouble(f[1]);
            return period > 0 ? Optional.of(quota / period) : Optional.empty();
        } catch (NumberFormatException e) {
            return Optional.empty();
        }
    }

    /**
     * @param text a file of {@code key: value} or {@code key\t: value} lines
     * @param key the key
     * @return the first value of that key, stripped
     */
    static Optional<String> field(String text, String key) {
        for (String line : text.lines().toList()) {
            int colon = line.indexOf(':');
            if (colon > 0 && line.substring(0, colon).strip().equals(key)) {
                return Optional.of(line.substring(colon + 1).strip());
            }
        }
        return Optional.empty();
    }

    private static long parseLongOrMinus(String s) {
        try {
            return Long.parseLong(s.strip());
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    /** @return the CPUs the cgroup and affinity leave this process, smallest of the limits */
    public double usableCpus() {
        List<Double> limits = new ArrayList<>();
        int logical = logicalCpus();
        if (logical > 0) {
            limits.add((double) logical);
        }
        Integer affinity = affinityCpus();
        if (affinity != null) {
            limits.add((double) affinity);
        }
        Double quota = cgroupQuotaCpus();
        if (quota != null) {
            limits.add(quota);
        }
        return limits.stream().mapToDouble(Double::doubleValue).min().orElse(Runtime.getRuntime().availableProcessors());
    }
}
