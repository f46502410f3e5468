package io.rtaware.experiment;

import com.fasterxml.jackson.annotation.JsonIgnore;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.core.conditions.HostFiles;
import io.rtaware.core.conditions.HostReader;
import io.rtaware.core.report.ReportDocument;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The conditions an experiment ran under, stated in its report so the numbers are read
 * honestly: the course, the time scale (how much slower a computer is emulated), the seed, the
 * occupancy grid's resolution, the runs per set and the machine. Written to
 * {@code experiment.json} when the experiment starts; when that file is missing, the report
 * rebuilds all but the machine from {@code results.csv}.
 *
 * @param scenario the course
 * @param timeScale world time runs this many times faster than wall time
 * @param seed world seed of run 1 of set 1 (the others follow by the design)
 * @param gridResolutionM grid cell size in metres, or null for {@code run}'s default
 * @param runsPerSet runs planned per set
 * @param machine the machine the runs were made on, or null if not recorded
 * @param design {@link ExperimentDesign#label()} of the runs ({@code independent} or
 *     {@code blocked}), or null in a folder made before the design was recorded (all blocked:
 *     {@link #experimentDesign()})
 * @param cpuLimitCpus the CPU quota each run's JVM ran under ({@code --cpu-limit}), or null for none
 */
public record ExperimentProfile(String scenario, double timeScale, long seed, Double gridResolutionM,
                                int runsPerSet, String machine, String design, Double cpuLimitCpus) {

    /** The profile's file name inside an experiment folder. */
    public static final String FILE_NAME = "experiment.json";

    private static final ObjectMapper MAPPER = ReportDocument.mapper();

    /**
     * @param plan the experiment's plan
     * @param machine a description of this machine
     * @return the profile
     */
    public static ExperimentProfile of(ExperimentPlan plan, String machine) {
        RunConditions c = plan.conditions();
        return new ExperimentProfile(c.scenario(), c.timeScale(), c.seed(), c.gridResolutionM(), plan.runsPerSet(), machine,
                c.design().label(), c.cpuLimitCpus());
    }

    /**
     * @param runs runs planned per set
     * @param machines the machines the runs were made on, or null
     * @return this profile with those
     */
    public ExperimentProfile withRunsAndMachine(int runs, String machines) {
        return new ExperimentProfile(scenario, timeScale, seed, gridResolutionM, runs, machines, design, cpuLimitCpus);
    }

    /**
     * @return the design of the runs; {@link ExperimentDesign#BLOCKED} for a folder made before it
     *     was recorded, since every run j then shared seed j across the sets
     */
    @JsonIgnore
    public ExperimentDesign experimentDesign() {
        return design == null ? ExperimentDesign.BLOCKED : ExperimentDesign.parse(design);
    }

    /**
     * @param rows the results of an experiment (at least one)
     * @return the profile implied by the first row; the machine is unknown
     */
    public static ExperimentProfile fromResults(List<RunResult> rows) {
        RunConditions c = rows.get(0).conditions();
        int runs = rows.stream().mapToInt(RunResult::run).max().orElse(0);
        return new ExperimentProfile(c.scenario(), c.timeScale(), c.seed(), c.gridResolutionM(), runs, null,
                c.design().label(), c.cpuLimitCpus());
    }

    /**
     * @param dir an experiment folder
     * @throws IOException if writing fails
     */
    public void write(Path dir) throws IOException {
        Files.writeString(dir.resolve(FILE_NAME), MAPPER.writeValueAsString(this) + "\n");
    }

    /**
     * @param dir an experiment folder
     * @return its profile, if {@code experiment.json} is there and readable; a file written before the
     *     design was recorded reads as {@code blocked}
     */
    public static Optional<ExperimentProfile> read(Path dir) {
        Path file = dir.resolve(FILE_NAME);
        if (!Files.exists(file)) {
            return Optional.empty();
        }
        try {
            ExperimentProfile p = MAPPER.readValue(file.toFile(), ExperimentProfile.class);
            // A file without the design predates it: its runs were blocked, and the summary says so.
            return Optional.of(p.design() != null ? p : new ExperimentProfile(p.scenario(), p.timeScale(), p.seed(),
                    p.gridResolutionM(), p.runsPerSet(), p.machine(), ExperimentDesign.BLOCKED.label(), p.cpuLimitCpus()));
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    /**
     * @return this machine: CPU model, CPUs (and those this process may use), kernel, hypervisor
     *     where the kernel names it, clock source and Java version, read by the core's
     *     {@link HostReader}
     */
    public static String describeThisMachine() {
        HostReader host = new HostReader(HostFiles.system(), System::nanoTime);
        String hypervisor = host.hypervisor();
        Boolean virtual = host.virtualized();
        return String.format(Locale.ROOT, "%s, %d CPUs (%s usable), Linux %s, %s, clock %s, Java %s (%s)", host.cpuModel(),
                host.logicalCpus(), new java.math.BigDecimal(host.usableCpus()).stripTrailingZeros().toPlainString(),
                host.kernel(), virtual == null ? "virtualization unknown" : virtual ? "virtual machine"
                        + (hypervisor == null ? "" : " (" + hypervisor + ")") : "not virtualized", host.clockSource(),
                System.getProperty("java.vm.version"), System.getProperty("java.vm.vendor"));
    }
}
