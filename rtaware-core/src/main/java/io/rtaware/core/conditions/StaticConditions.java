package io.rtaware.core.conditions;

import java.util.List;

/**
 * What a run's numbers depend on and that does not change during it: the machine, the
 * operating system, the JVM, rtaware's build and the run's own settings.
 *
 * @param cpuModel the CPU's model name
 * @param logicalCpus CPUs the OS counts
 * @param affinityCpus CPUs the process's affinity allows, or null if unknown
 * @param cgroupQuotaCpus the cgroup's CPU quota in CPUs, or null if none
 * @param usableCpus the CPUs this process may use: the smallest of the three above
 * @param kernel the kernel's release
 * @param virtualized true on a virtual machine (the CPU flags say {@code hypervisor}), null if unknown
 * @param hypervisor the hypervisor where the kernel names it, else null
 * @param clockSource the kernel's clock source, e.g. {@code tsc}
 * @param jvmVendor the JVM's vendor
 * @param jvmVersion the JVM's version
 * @param jvmOptions the JVM's start options
 * @param collectors the JVM's collectors
 * @param heapMaxMb the JVM's maximum heap, MiB, or -1 if unknown
 * @param rtawareVersion rtaware's version
 * @param gitCommit the checkout's commit when run from one, else null
 * @param timeScale world seconds per wall second of the run
 * @param realtime the real-time settings in use ({@code none} when none)
 */
public record StaticConditions(String cpuModel, int logicalCpus, Integer affinityCpus, Double cgroupQuotaCpus,
                               double usableCpus, String kernel, Boolean virtualized, String hypervisor,
                               String clockSource, String jvmVendor, String jvmVersion, List<String> jvmOptions,
                               List<String> collectors, long heapMaxMb, String rtawareVersion, String gitCommit,
                               double timeScale, String realtime) {

    /**
     * Copies the lists.
     *
     * @param cpuModel the CPU's model name
     * @param logicalCpus CPUs the OS counts
     * @param affinityCpus CPUs the process's affinity allows, or null if unknown
     * @param cgroupQuotaCpus the cgroup's CPU quota in CPUs, or null if none
     * @param usableCpus the CPUs this process may use
     * @param kernel the kernel's release
     * @param virtualized true on a virtual machine, null if unknown
     * @param hypervisor the hypervisor where the kernel names it, else null
     * @param clockSource the kernel's clock source
     * @param jvmVendor the JVM's vendor
     * @param jvmVersion the JVM's version
     * @param jvmOptions the JVM's start options (copied)
     * @param collectors the JVM's collectors (copied)
     * @param heapMaxMb the JVM's maximum heap, MiB, or -1 if unknown
     * @param rtawareVersion rtaware's version
     * @param gitCommit the checkout's commit when run from one, else null
     * @param timeScale world seconds per wall second of the run
     * @param realtime the real-time settings in use
     */
    public StaticConditions {
        jvmOptions = List.copyOf(jvmOptions);
        collectors = List.copyOf(collectors);
    }

    /**
     * @param host the machine
     * @param jvm the JVM
     * @param build rtaware's build
     * @param timeScale the run's time scale
     * @param realtime the run's real-time settings, or {@code none}
     * @return the conditions read now
     */
    public static StaticConditions read(HostReader host, JvmProbe jvm, BuildInfo build, double timeScale,
                                        String realtime) {
        long heap = jvm.heapMaxBytes();
        return new StaticConditions(host.cpuModel(), host.logicalCpus(), host.affinityCpus(), host.cgroupQuotaCpus(),
                host.usableCpus(), host.kernel(), host.virtualized(), host.hypervisor(), host.clockSource(),
                jvm.vendor(), jvm.version(), jvm.options(), jvm.collectors(), heap < 0 ? -1 : heap >> 20,
                build.version(), build.gitCommit(), timeScale, realtime);
    }
}
