package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.experiment.report.ExperimentReport;
import io.rtaware.experiment.report.MapBackground;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An experiment whose run of seed 2 was made beside another process (the fake run reports it
 * busy): results.csv labels it, the summary leaves it out unless busy runs are included, and
 * report.md says how many runs of each kind there were and why one is left out.
 */
class QuietRunsTest {

    @TempDir
    Path dir;

    private List<RunResult> runExperiment() throws Exception {
        ExperimentPlan plan = new ExperimentPlan(ExperimentSets.paper().subList(0, 2), 3,
                new RunConditions("busy-seed-2", 10, 1, null));
        ProgressBar bar = new ProgressBar(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8),
                false, System::nanoTime, 1);
        return new ExperimentRunner(plan, JvmRunCommand.ofCurrentProcess(FakeRun.class.getName()), dir, bar).run();
    }

    @Test
    void busyRunsAreLabelledInTheResultsAndLeftOutOfTheSummary() throws Exception {
        List<RunResult> rows = runExperiment();
        assertEquals(6, rows.size());
        for (RunResult r : rows) {
            assertEquals(r.run() == 2 ? "busy" : "quiet", r.machine().machine(), "set " + r.set() + " run " + r.run());
        }
        assertEquals(1.2, rows.stream().filter(r -> r.run() == 2).findFirst().orElseThrow().machine().otherCpus());
        assertEquals(2, ResultsCsv.read(dir.resolve(ResultsCsv.FILE_NAME)).get(0).machine().machineCpus(),
                "the machine's CPUs from the run's conditions, through results.csv");
        assertTrue(Files.readString(dir.resolve(ResultsCsv.FILE_NAME)).contains(
                ",busy,other processes used 1.2 of 2 CPUs (more than 0.10),1.2,0,3.5,0.4,"), "results.csv columns");

        ExperimentSummary quiet = ExperimentReport.render(dir, MapBackground.none());
        assertEquals(2, quiet.sets().get(0).runs(), "set 1 counts its 2 quiet runs");
        ExperimentConditions c = quiet.conditions();
        assertEquals(6, c.runs());
        assertEquals(4, c.used());
        assertEquals(java.util.Map.of("busy", 2, "quiet", 4), c.byMachine());
        assertEquals(List.of("set 1 run 2: busy (other processes used 1.2 of 2 CPUs (more than 0.10))",
                "set 2 run 2: busy (other processes used 1.2 of 2 CPUs (more than 0.10))"), c.leftOut());
        assertEquals(0.02, c.otherCpus().max(), 1e-12, "the spread is over the used runs");
        String md = Files.readString(dir.resolve(ExperimentReport.MARKDOWN_FILE));
        assertTrue(md.contains("Machine during the runs: 6 run(s): 2 busy, 4 quiet. This report (tables, t-tests, claims, "
                + "figures) uses the 4 quiet run(s) only"), md);
        assertTrue(md.contains("Left out: set 1 run 2: busy"), md);
        JsonNode summary = new ObjectMapper().readTree(dir.resolve(ExperimentReport.SUMMARY_FILE).toFile());
        assertEquals(4, summary.path("conditions").path("used").asInt());

        ExperimentSummary all = ExperimentReport.render(dir, MapBackground.none(), true);
        assertEquals(3, all.sets().get(0).runs(), "--include-busy counts every run");
        assertTrue(Files.readString(dir.resolve(ExperimentReport.MARKDOWN_FILE)).contains("uses all 6 of them (--include-busy)"));
    }

    @Test
    void theOrderOfTheRunsIsRecordedInThePlan() throws Exception {
        runExperiment();
        JsonNode plan = new ObjectMapper().readTree(dir.resolve(PlanFile.FILE_NAME).toFile());
        List<String> order = new java.util.ArrayList<>();
        plan.path("order").forEach(n -> order.add(n.asText()));
        assertEquals(List.of("set1-run1", "set2-run1", "set1-run2", "set2-run2", "set1-run3", "set2-run3"), order,
                "sets interleaved over time");
    }

    @Test
    void resultsWithoutQuietRunsAreReportedOnlyWhenBusyRunsAreIncluded() throws Exception {
        RunResult old = new RunResult(1, 1, ExperimentSets.paper().get(0), new RunConditions("paper-room", 10, 1, null),
                "completed", 250, 0.2, 20, 0, 4, 4, java.util.Map.of());
        ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), old);
        ExperimentInputException e = assertThrows(ExperimentInputException.class,
                () -> ExperimentReport.render(dir, MapBackground.none()));
        assertTrue(e.getMessage().contains("none of its 1 runs was made on a quiet machine (1 unrecorded); "),
                e.getMessage());
    }

    /** experiment --allow-busy where no run was quiet ran every run, then refused to report them. */
    @Test
    void runsAskedForOnABusyMachineAreReportedLabelledBusy() throws Exception {
        RunMachine machine = new RunMachine("busy", "other processes used 1.2 of 2 CPUs (more than 0.10)", 1.2, 0, 0.4,
                0.4, 0.1, Double.NaN, "busy", 0, 2);
        for (int run = 1; run <= 2; run++) {
            ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), new RunResult(1, run, ExperimentSets.paper().get(0),
                    new RunConditions("paper-room", 10, run, null), "completed", 250, 0.2, 20, 0, 4, 4,
                    java.util.Map.of()).withMachine(machine));
        }
        assertThrows(ExperimentInputException.class, () -> ExperimentReport.render(dir, MapBackground.none()),
                "without --allow-busy such a folder is still refused");
        ExperimentSummary s = ExperimentReport.render(dir, MapBackground.none(), false, true);
        assertEquals(2, s.conditions().used(), "every run is used");
        assertTrue(s.conditions().busyOnly());
        String md = Files.readString(dir.resolve(ExperimentReport.MARKDOWN_FILE));
        assertTrue(md.startsWith("# rtaware experiment report\n\n**Busy machine.** Not one run of this report was made on a "
                + "machine known to be quiet (2 busy): "), md);
        JsonNode summary = new ObjectMapper().readTree(dir.resolve(ExperimentReport.SUMMARY_FILE).toFile());
        assertEquals(0, summary.path("conditions").path("quiet_used").asInt(-1), summary.path("conditions").toString());
    }
}
