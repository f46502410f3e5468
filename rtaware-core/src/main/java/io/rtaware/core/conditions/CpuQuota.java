package io.rtaware.core.conditions;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * A CPU quota for processes, as a child cgroup of the machine's CPU controller: cgroup v2's
 * {@code cpu.max} where the unified hierarchy has the {@code cpu} controller, else cgroup v1's
 * {@code cpu.cfs_quota_us} over {@code cpu.cfs_period_us}. It emulates a slower computer the way
 * the paper's robot was one: every thread of the processes placed in it (the controller, its
 * built-in Player server, the JIT and the collector) shares the quota, so tasks that ask for more
 * CPU than there is miss their deadlines, and a heavy task takes CPU from the others.
 *
 * <p>{@link #create} makes the group ({@value #NAME_PREFIX}NAME under the controller's root, its
 * period {@value #PERIOD_US} us, its quota {@code cpus} times that); {@link #add} moves a process
 * into it (all its threads: {@code cgroup.procs}); {@link #close} moves every process still in it
 * back to the controller's root group and removes it. The processes return to the root group, not
 * to a group they were in before: rtaware places its own run processes, which start in the root
 * group on the machines it targets (a VM or a container's own root), and leaves them there only
 * for the moment before they exit. Creating a group needs root or a delegated hierarchy; where
 * neither version's controller is there and writable, {@link #create} throws
 * {@link Unavailable} with one line saying which files it looked for and what failed.
 *
 * <p>All file operations go through {@link Writes}, the operating system's in production and a
 * fixture tree in tests. {@link #add} is for one thread; {@link #close} may be called more than
 * once and from any thread (a shutdown hook).
 */
public final class CpuQuota implements AutoCloseable {

    /** The period of the quota, microseconds: the kernel's default CFS period. */
    public static final long PERIOD_US = 100_000;
    /** The smallest quota the kernel takes, 1 ms per period: 0.01 CPUs. */
    public static final double MIN_CPUS = 0.01;
    /** The most CPUs a quota may name: far more than any machine rtaware runs on has. */
    public static final double MAX_CPUS = 1024;
    /** The start of every group's name, so a group left behind by a killed process can be recognised. */
    public static final String NAME_PREFIX = "rtaware-";
    /** Where the machine's cgroup hierarchies are mounted. */
    public static final Path SYSTEM_ROOT = Path.of("/sys/fs/cgroup");

    /** The cgroup version whose CPU controller holds the quota. */
    public enum Version {
        /** cgroup v1: {@code cpu.cfs_quota_us} and {@code cpu.cfs_period_us} in the {@code cpu} hierarchy. */
        V1,
        /** cgroup v2: {@code cpu.max} in the unified hierarchy. */
        V2
    }

    /** The quota cannot be set on this machine: one line naming what is missing or what failed. */
    public static final class Unavailable extends Exception {
        private static final long serialVersionUID = 1L;

        /** @param message the line to show */
        public Unavailable(String message) {
            super(message);
        }
    }

    /** The file operations a quota needs; {@link #SYSTEM} does them on the real files. */
    public interface Writes {
        /**
         * @param dir a folder to create (its parent exists)
         * @throws IOException if it cannot be created
         */
        void createDirectory(Path dir) throws IOException;

        /**
         * @param file a control file
         * @param text what to write to it
         * @throws IOException if the kernel refuses the value or the file is not writable
         */
        void write(Path file, String text) throws IOException;

        /**
         * @param dir an empty group to remove
         * @throws IOException if it cannot be removed (a process is still in it)
         */
        void removeDirectory(Path dir) throws IOException;
    }

    /** The operating system's files: {@code mkdir}, a write of the whole value, {@code rmdir}. */
    public static final Writes SYSTEM = new Writes() {
        @Override
        public void createDirectory(Path dir) throws IOException {
            Files.createDirectory(dir);
        }

        @Override
        public void write(Path file, String text) throws IOException {
            Files.writeString(file, text);
        }

        @Override
        public void removeDirectory(Path dir) throws IOException {
            Files.delete(dir);
        }
    };

    private final Version version;
    private final Path controllerRoot;
    private final Path group;
    private final double cpus;
    private final Writes writes;
    private boolean closed;

    private CpuQuota(Version version, Path controllerRoot, Path group, double cpus, Writes writes) {
        this.version = version;
        this.controllerRoot = controllerRoot;
        this.group = group;
        this.cpus = cpus;
        this.writes = writes;
    }

    /**
     * @param cpus a quota in CPUs
     * @return why it cannot be a quota, or null if it can
     */
    public static String invalid(double cpus) {
        if (!(cpus >= MIN_CPUS && cpus <= MAX_CPUS)) {
            return String.format(Locale.ROOT, "must be a number of CPUs from %s to %s, got %s", MIN_CPUS, (long) MAX_CPUS,
                    cpus);
        }
        return null;
    }

    /**
     * Finds the CPU controller under {@code root}: v2 when {@code root/cgroup.controllers} lists
     * {@code cpu}, else v1 when {@code root/cpu/cpu.cfs_quota_us} (or {@code root/cpu,cpuacct/...})
     * exists.
     *
     * @param root where the hierarchies are mounted ({@link #SYSTEM_ROOT} on the machine)
     * @return the version and the folder of the controller's root group
     * @throws Unavailable if neither is there
     */
    static Found find(Path root) throws Unavailable {
        Path controllers = root.resolve("cgroup.controllers");
        if (Files.isRegularFile(controllers) && readTokens(controllers).contains("cpu")) {
            return new Found(Version.V2, root);
        }
        for (String name : List.of("cpu", "cpu,cpuacct", "cpuacct,cpu")) {
            Path dir = root.resolve(name);
            if (Files.isRegularFile(dir.resolve("cpu.cfs_quota_us"))) {
                return new Found(Version.V1, dir);
            }
        }
        throw new Unavailable("--cpu-limit needs a CPU controller: neither cgroup v2 (" + controllers
                + " lists no 'cpu') nor cgroup v1 (no " + root.resolve("cpu").resolve("cpu.cfs_quota_us") + ") is there");
    }

    /**
     * A CPU controller found.
     *
     * @param version the cgroup version
     * @param controllerRoot the folder of the controller's root group
     */
    record Found(Version version, Path controllerRoot) {
    }

    /**
     * Creates the group and sets its quota.
     *
     * @param root where the hierarchies are mounted ({@link #SYSTEM_ROOT} on the machine)
     * @param name the group's name after {@value #NAME_PREFIX}, e.g. the process id
     * @param cpus the quota in CPUs, {@value #MIN_CPUS} to {@value #MAX_CPUS}
     * @param writes the file operations ({@link #SYSTEM} on the machine)
     * @return the quota, to {@link #add} processes to and {@link #close}
     * @throws Unavailable if no CPU controller is there, or it is not writable here (one line)
     * @throws IllegalArgumentException if {@code cpus} is out of range or the name is not a plain name
     */
    public static CpuQuota create(Path root, String name, double cpus, Writes writes) throws Unavailable {
        String bad = invalid(cpus);
        if (bad != null) {
            throw new IllegalArgumentException("--cpu-limit " + bad);
        }
        if (name.isEmpty() || name.contains("/") || name.startsWith(".")) {
            throw new IllegalArgumentException("a cgroup name must be a plain name, got '" + name + "'");
        }
        Found found = find(root);
        Path group = found.controllerRoot().resolve(NAME_PREFIX + name);
        long quotaUs = Math.round(cpus * PERIOD_US);
        try {
            if (found.version() == Version.V2) {
                writes.write(found.controllerRoot().resolve("cgroup.subtree_control"), "+cpu");
            }
            writes.createDirectory(group);
        } catch (IOException e) {
            throw new Unavailable("--cpu-limit: cannot create the cgroup " + group + " (" + reason(e)
                    + "); it needs root or a delegated cgroup " + found.version().name().toLowerCase(Locale.ROOT)
                    + " hierarchy");
        }
        CpuQuota quota = new CpuQuota(found.version(), found.controllerRoot(), group, cpus, writes);
        try {
            if (found.version() == Version.V2) {
                writes.write(group.resolve("cpu.max"), quotaUs + " " + PERIOD_US);
            } else {
                writes.write(group.resolve("cpu.cfs_period_us"), Long.toString(PERIOD_US));
                writes.write(group.resolve("cpu.cfs_quota_us"), Long.toString(quotaUs));
            }
        } catch (IOException e) {
            quota.close();
            throw new Unavailable("--cpu-limit: cannot set the quota of " + group + " (" + reason(e) + ")");
        }
        return quota;
    }

    /**
     * Places this process under a quota until it exits: a group named after its pid, this process
     * moved into it, and a shutdown hook that moves it back and removes the group (so Ctrl-C,
     * SIGTERM and {@code System.exit} clean up too; SIGKILL leaves an empty
     * {@value #NAME_PREFIX}PID group, which {@code rmdir} removes).
     *
     * <p>{@code rtaware run --cpu-limit} moves its own process rather than starting the run again in
     * a child JVM: the process that measures the run (its conditions, its report) is then the one
     * under the quota, with every thread it has or will start (the controller, the built-in server,
     * the JIT and the collector), and there is no second JVM to forward Ctrl-C to and wait for. It
     * moves before it starts any server or task, so only the argument parsing ran unlimited.
     * {@code rtaware experiment --cpu-limit} passes the option to each run, whose fresh JVM moves
     * itself the same way.
     *
     * @param cpus the quota in CPUs
     * @return the quota; closing it early does what the hook would
     * @throws Unavailable if {@code cpus} is out of range or the quota cannot be set here (one line)
     */
    public static CpuQuota confineThisProcess(double cpus) throws Unavailable {
        checkCpus(cpus);
        long pid = ProcessHandle.current().pid();
        CpuQuota quota = create(SYSTEM_ROOT, Long.toString(pid), cpus, SYSTEM);
        try {
            quota.add(pid);
        } catch (IOException e) {
            quota.close();
            throw new Unavailable("--cpu-limit: cannot move this process into " + quota.group + " (" + reason(e) + ")");
        }
        Runtime.getRuntime().addShutdownHook(new Thread(quota::close, "rtaware-cpu-quota-removal"));
        return quota;
    }

    /**
     * Checks that a quota can be set here: creates a group and removes it at once.
     *
     * @param cpus the quota in CPUs
     * @throws Unavailable if {@code cpus} is out of range or the quota cannot be set here (one line)
     */
    public static void probe(double cpus) throws Unavailable {
        checkCpus(cpus);
        create(SYSTEM_ROOT, ProcessHandle.current().pid() + "-probe", cpus, SYSTEM).close();
    }

    /**
     * @param cpus a quota in CPUs, or null for none
     * @return the one-line reason a quota of {@code cpus} cannot be set here ({@link #probe}), or
     *     empty when it can or none is asked for
     */
    public static Optional<String> refusal(Double cpus) {
        if (cpus == null) {
            return Optional.empty();
        }
        try {
            probe(cpus);
            return Optional.empty();
        } catch (Unavailable e) {
            return Optional.of(e.getMessage());
        }
    }

    /**
     * @param pid a process to move into the group, all its threads
     * @throws IOException if the kernel refuses
     */
    public void add(long pid) throws IOException {
        writes.write(group.resolve("cgroup.procs"), Long.toString(pid));
    }

    /** @return the quota in CPUs */
    public double cpus() {
        return cpus;
    }

    /** @return the group's folder */
    public Path group() {
        return group;
    }

    /** @return e.g. {@code 0.5 CPUs (cgroup v1 cpu.cfs_quota_us 50000 per cpu.cfs_period_us 100000)} */
    public String describe() {
        long quotaUs = Math.round(cpus * PERIOD_US);
        String files = version == Version.V2 ? "cpu.max " + quotaUs + " " + PERIOD_US
                : "cpu.cfs_quota_us " + quotaUs + " per cpu.cfs_period_us " + PERIOD_US;
        return new java.math.BigDecimal(Double.toString(cpus)).stripTrailingZeros().toPlainString() + " CPUs (cgroup "
                + version.name().toLowerCase(Locale.ROOT) + " " + files + ")";
    }

    /**
     * Moves every process still in the group back to the controller's root group and removes the
     * group. Failures are not thrown (it runs in shutdown hooks): a group that cannot be removed
     * stays, empty once its processes exit, named {@value #NAME_PREFIX}....
     */
    @Override
    public synchronized void close() {
        if (closed) {
            return;
        }
        closed = true;
        try {
            Path procs = group.resolve("cgroup.procs");
            List<String> pids = Files.isReadable(procs) ? Files.readAllLines(procs) : List.of();
            for (String pid : pids) {
                if (!pid.isBlank()) {
                    writes.write(controllerRoot.resolve("cgroup.procs"), pid.strip());
                }
            }
            writes.removeDirectory(group);
        } catch (IOException e) {
            System.err.println("rtaware: could not remove the cgroup " + group + " (" + reason(e)
                    + "); remove it with rmdir once its processes have ended");
        }
    }

    private static void checkCpus(double cpus) throws Unavailable {
        String bad = invalid(cpus);
        if (bad != null) {
            throw new Unavailable("--cpu-limit " + bad);
        }
    }

    private static List<String> readTokens(Path file) {
        try {
            return List.of(Files.readString(file).strip().split("\\s+"));
        } catch (IOException e) {
            return List.of();
        }
    }

    private static String reason(IOException e) {
        String message = e.getMessage();
        return e.getClass().getSimpleName() + (message == null ? "" : ": " + message);
    }

    /** @return the cgroup version of this quota */
    public Version version() {
        return version;
    }

    @Override
    public String toString() {
        return describe() + " at " + group;
    }
}
