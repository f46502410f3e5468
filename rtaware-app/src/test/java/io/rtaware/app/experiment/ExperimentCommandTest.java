package io.rtaware.app.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import io.rtaware.app.CliRun;
import io.rtaware.app.RtawareCli;
import io.rtaware.experiment.ExperimentDesign;
import io.rtaware.experiment.ExperimentPlan;
import io.rtaware.experiment.RunConditions;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class ExperimentCommandTest {

    @TempDir
    Path dir;

    @Test
    void badInputIsAUserErrorAndCreatesNothing() throws Exception {
        Path out = dir.resolve("exp");
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("experiment", "--runs", "0", "--out", out.toString()));
        // Issue 24: two billion runs per set ran out of heap building the plan.
        CliRun.of("experiment", "--runs", "2000000000", "--out", out.toString())
                .assertOneLineUserError("--runs must be in 1..10000, got 2000000000");
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("experiment", "--time-scale", "-1", "--out", out.toString()));
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("experiment", "--sets", dir.resolve("none.yaml").toString(),
                "--out", out.toString()));
        Path bad = dir.resolve("bad.yaml");
        Files.writeString(bad, "sets:\n  - periods_ms: {waypoint: 0}\n");
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("experiment", "--sets", bad.toString(), "--out", out.toString()));
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("experiment", "--resume", "--out", out.toString()));
        Path badSweep = dir.resolve("sweep.yaml");
        Files.writeString(badSweep, "sweep:\n  periods_ms: [10]\n  top_speed_mps: -1\n");
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("experiment", "--sets", badSweep.toString(), "--out", out.toString()));
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("experiment", "--shard", "3/2", "--out", out.toString()));
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("experiment", "--sets", "sweep-obstacle", "--runs", "1",
                "--shard", "99/100", "--out", out.toString()));
        CliRun.of("experiment", "--design", "paired", "--out", out.toString())
                .assertOneLineUserError("the design must be one of [independent, blocked], got 'paired'");
        CliRun.of("experiment", "--robots", "0", "--out", out.toString())
                .assertOneLineUserError("--robots must be at least 1, got 0");
        CliRun.of("experiment", "--cpu-limit", "0.001", "--out", out.toString())
                .assertOneLineUserError("--cpu-limit must be a number of CPUs from 0.01 to 1024, got 0.001");
        CliRun.of("run", "--cpu-limit", "0", "--out", out.toString())
                .assertOneLineUserError("--cpu-limit must be a number of CPUs from 0.01 to 1024, got 0.0");
        assertFalse(Files.exists(out));
    }

    @Test
    void theDesignAndThePopulationComeFromTheOptions() {
        assertEquals(RunConditions.ofPopulation("paper-room", 10, 1, null, null, null, ExperimentDesign.INDEPENDENT),
                planOf().conditions());
        assertEquals(new RunConditions("paper-room", 10, 3, null, 4, 1, ExperimentDesign.BLOCKED),
                planOf("--design", "blocked", "--robot-seed", "4", "--seed", "3").conditions());
        assertEquals(new RunConditions("paper-room", 10, 1, null, 1, 50, ExperimentDesign.INDEPENDENT),
                planOf("--robots", "50").conditions());
        assertEquals(0.5, planOf("--cpu-limit", "0.5").conditions().cpuLimitCpus());
    }

    private static ExperimentPlan planOf(String... args) {
        ExperimentCommand command = new ExperimentCommand();
        new CommandLine(command).parseArgs(args);
        return command.plan();
    }

    @Test
    void reportNeedsAnExperimentFolder() {
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("report", dir.resolve("missing").toString()));
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("report", dir.toString()));
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("report", dir.toString(), dir.toString()));
        assertEquals(RtawareCli.EXIT_USER_ERROR, RtawareCli.execute("report", dir.toString(), "--out", dir.resolve("m").toString()));
    }
}
