package io.rtaware.app.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import io.rtaware.experiment.ExperimentPlan;
import io.rtaware.experiment.ExperimentProfile;
import io.rtaware.experiment.ExperimentSets;
import io.rtaware.experiment.FolderLock;
import io.rtaware.experiment.PeriodSet;
import io.rtaware.experiment.PlanFile;
import io.rtaware.experiment.ResultsCsv;
import io.rtaware.experiment.RunConditions;
import io.rtaware.experiment.RunResult;
import io.rtaware.experiment.TaskResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** An experiment folder: one writer at a time, and --resume continues the plan stored in it. */
class ExperimentFolderTest {

    @TempDir
    Path dir;

    /** A finished 1 set x 1 run experiment at time scale 20, seed 5: resuming it runs nothing and re-renders the report. */
    private ExperimentPlan finishedExperiment(boolean withPlanFile) throws Exception {
        return finishedExperiment(withPlanFile, "paper-room");
    }

    /** The same on a course given as a scenario file. */
    private ExperimentPlan finishedExperiment(boolean withPlanFile, String scenario) throws Exception {
        PeriodSet set = ExperimentSets.paper().get(3);
        ExperimentPlan plan = new ExperimentPlan(List.of(set), 1, new RunConditions(scenario, 20, 5, null));
        if (withPlanFile) {
            PlanFile.write(dir, plan);
        }
        ExperimentProfile.of(plan, "test machine").write(dir);
        ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), new RunResult(1, 1, set, plan.conditions(), "completed",
                12.0, 0.2, 3.0, 0, 4, 4, Map.of()).withMachine(new io.rtaware.experiment.RunMachine("quiet", "", 0.01, 0,
                0.2, 0.2, 0.1, Double.NaN, "quiet", 0, 2)));
        return plan;
    }

    @Test
    void resumeTakesThePlanFromTheFolder() throws Exception {
        finishedExperiment(true);
        CliRun r = CliRun.of("experiment", "--resume", "--out", dir.toString());
        assertEquals(0, r.status(), r.toString());
        assertTrue(r.out().contains("1 set(s) x 1 run(s) of paper-room at time scale x20.0"), r.out());
        assertTrue(Files.exists(dir.resolve("report.md")), "the report is rendered");
    }

    @Test
    void resumeOfAFolderWithoutPlanFileUsesItsProfileAndResults() throws Exception {
        finishedExperiment(false);
        CliRun r = CliRun.of("experiment", "--resume", "--out", dir.toString());
        assertEquals(0, r.status(), r.toString());
        assertTrue(r.out().contains("1 set(s) x 1 run(s) of paper-room at time scale x20.0"), r.out());
    }

    @Test
    void resumeRefusesAnOptionThatContradictsTheFolder() throws Exception {
        finishedExperiment(true);
        CliRun.of("experiment", "--resume", "--out", dir.toString(), "--time-scale", "10")
                .assertOneLineUserError("--time-scale 10.0 differs from its 20.0");
    }

    @Test
    void aFolderOwnedByALiveExperimentIsRefused() throws Exception {
        finishedExperiment(true);
        Process owner = new ProcessBuilder("sleep", "60").start();
        try {
            Files.writeString(dir.resolve(FolderLock.FILE_NAME), owner.pid() + "\n");
            CliRun.of("experiment", "--resume", "--out", dir.toString())
                    .assertOneLineUserError("is in use by another rtaware experiment (pid " + owner.pid());
        } finally {
            owner.destroyForcibly().waitFor();
        }
        CliRun r = CliRun.of("experiment", "--resume", "--out", dir.toString());
        assertEquals(0, r.status(), "taken over once the owner is dead: " + r);
        assertTrue(Files.notExists(dir.resolve(FolderLock.FILE_NAME)), "released at the end");
    }

    @Test
    void aDuplicatedRowIsOneLineWithItsLineNumber() throws Exception {
        ExperimentPlan plan = finishedExperiment(true);
        ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), new RunResult(1, 1, plan.sets().get(0), plan.conditions(),
                "completed", 12.0, 0.2, 3.0, 0, 4, 4, Map.of()));
        CliRun.of("experiment", "--resume", "--out", dir.toString()).assertOneLineUserError("line 3: set 1 run 1 is already on line 2");
        CliRun.of("report", dir.toString()).assertOneLineUserError("line 3: set 1 run 1 is already on line 2");
    }

    /** A plan of 1 set x 2 runs, both finished, the second run's row as its text. */
    private String twoRunExperiment() throws Exception {
        PeriodSet set = ExperimentSets.paper().get(3);
        ExperimentPlan plan = new ExperimentPlan(List.of(set), 2, new RunConditions("paper-room", 20, 5, null));
        PlanFile.write(dir, plan);
        ExperimentProfile.of(plan, "test machine").write(dir);
        ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), new RunResult(1, 1, set, plan.conditions(), "completed",
                12.0, 0.2, 3.0, 0, 4, 4, Map.of()));
        RunResult second = new RunResult(1, 2, set, plan.conditions(), "completed", 12.345, 0.2, 3.0, 0, 4, 4,
                Map.of("planner", new TaskResult(1111, 5, 0.45, 0, 100.0)));
        ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), second);
        return ResultsCsv.format(second);
    }

    /**
     * Issue 34: with --allow-busy and no run on a quiet machine, experiment ran every run and then exited 2
     * without a report ("none of its 2 runs was made on a quiet machine ({busy=2})").
     */
    @Test
    void runsAllowedOnABusyMachineAreReportedLabelledBusy() throws Exception {
        PeriodSet set = ExperimentSets.paper().get(3);
        ExperimentPlan plan = new ExperimentPlan(List.of(set), 2, new RunConditions("paper-room", 20, 5, null));
        PlanFile.write(dir, plan);
        ExperimentProfile.of(plan, "test machine").write(dir);
        io.rtaware.experiment.RunMachine busy = new io.rtaware.experiment.RunMachine("busy",
                "other processes used 1.2 of 2 CPUs (more than 0.10)", 1.2, 0, 0.4, 0.4, 0.1, Double.NaN, "busy", 0, 2);
        for (int run = 1; run <= 2; run++) {
            ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), new RunResult(1, run, set, plan.conditions(), "completed",
                    12.0, 0.2, 3.0, 0, 4, 4, Map.of()).withMachine(busy));
        }
        CliRun refused = CliRun.of("experiment", "--resume", "--out", dir.toString());
        assertEquals(2, refused.status(), "without --allow-busy such a folder is refused");
        assertTrue(refused.err().contains("none of its 2 runs was made on a quiet machine (2 busy); report them labelled"
                + " with --include-busy"), refused.err());
        CliRun r = CliRun.of("experiment", "--resume", "--out", dir.toString(), "--allow-busy");
        assertEquals(0, r.status(), r.toString());
        assertTrue(r.out().contains("\nBUSY MACHINE: Not one run of this report was made on a machine known to be quiet "
                + "(2 busy)"), r.out());
        assertTrue(Files.readString(dir.resolve("report.md")).contains("**Busy machine.** Not one run"), "report.md");
    }

    /** Issue 24: --runs 1 on a folder of 2 runs per set lowered the stored plan and left run 2 outside it. */
    @Test
    void resumeNeverLowersThePlan() throws Exception {
        twoRunExperiment();
        CliRun.of("experiment", "--resume", "--out", dir.toString(), "--runs", "1")
                .assertOneLineUserError("--resume never lowers the plan of " + dir + ": --runs 1 is fewer than its 2");
        assertEquals(2, PlanFile.fromFolder(dir).runsPerSet(), "the stored plan is unchanged");
    }

    /** Issue 24: report merged rows of set 9, run 99, and impossible values (a miss rate of 110 964 %). */
    @Test
    void reportRefusesRowsOutsideThePlanAndImpossibleValuesNamingTheLine() throws Exception {
        String row = twoRunExperiment();
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        String good = Files.readString(csv);
        Files.writeString(csv, good + row.replaceFirst("^1,", "9,").replace(",2,", ",1,") + "\n");
        CliRun.of("report", dir.toString()).assertOneLineUserError("line 4: set 9 run 1 is outside the plan of " + dir
                + " (1 sets x 2 runs)");
        Files.writeString(csv, good + row.replace(",2,", ",99,") + "\n");
        CliRun.of("report", dir.toString()).assertOneLineUserError("line 4: set 1 run 99 is outside the plan");
        Files.writeString(csv, good.replace("1111,5,", "1111,2222,"));
        CliRun.of("report", dir.toString()).assertOneLineUserError("line 3: task 'planner': 2222 misses of 1111 releases");
        Files.writeString(csv, good.replace(",12.345,", ",-12.345,"));
        CliRun.of("report", dir.toString()).assertOneLineUserError("line 3: a negative run time or distance");
        Files.writeString(csv, good);
        assertEquals(0, CliRun.of("report", dir.toString(), "--include-busy").status(),
                "the folder as written is fine (its runs predate recorded conditions)");
    }

    /**
     * Issue 38: with the documented {@code --scenario /path/to/course.yaml} every run finished and
     * then no summary or report was written ("no id for claim"); report printed a stack trace.
     */
    @Test
    void aCourseGivenAsAFilePathIsReported() throws Exception {
        String course = dir.resolve("courses/hall.yaml").toString();
        finishedExperiment(true, course);
        CliRun r = CliRun.of("report", dir.toString());
        assertEquals(0, r.status(), r.toString());
        String summary = Files.readString(dir.resolve("summary.json"));
        assertTrue(summary.contains("\"id\" : \"slow-hits-on-hall\""), "the claim's id");
        assertTrue(summary.contains("robot hits walls and obstacles on " + course), "the claim names the course as given");
    }

    /** Issue 38: a report that cannot be written is one line that says the runs are kept, not a stack trace. */
    @Test
    void aReportThatCannotBeWrittenIsOneLine() throws Exception {
        finishedExperiment(true);
        Files.createDirectories(dir.resolve("summary.json"));
        CliRun r = CliRun.of("report", dir.toString());
        assertEquals(1, r.status(), r.toString());
        assertEquals(1, r.err().strip().lines().count(), "one line: " + r.err());
        assertTrue(r.err().contains("could not write the report of " + dir + ": " + dir.resolve("summary.json")
                + ": a folder, not a file; the runs are kept in " + dir.resolve("results.csv")), r.err());
    }

    /** Issue 38: report used a row whose periods were not its set's in plan.json. */
    @Test
    void reportRefusesARowWhosePeriodsAreNotThoseOfItsSetInThePlan() throws Exception {
        twoRunExperiment();
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        int planner = ResultsCsv.HEADER.indexOf("planner_period_ms");
        StringBuilder edited = new StringBuilder();
        for (String line : Files.readAllLines(csv)) {
            String[] fields = line.split(",", -1);
            if (!line.startsWith("set,")) {
                fields[planner] = "7"; // both rows agree, so only the plan can tell
            }
            edited.append(String.join(",", fields)).append('\n');
        }
        Files.writeString(csv, edited);
        CliRun.of("report", dir.toString(), "--include-busy").assertOneLineUserError(csv + " line 2: set 1 run 1 is 'Set 4' (");
        CliRun.of("report", "--include-busy", "--results", dir.resolve("RESULTS.md").toString(), dir.toString())
                .assertOneLineUserError(csv + " line 2: set 1 run 1 is 'Set 4' (");
    }

    /**
     * Issue 38: report used a row labelled quiet whose other processes used 5 CPUs, and a figure
     * above the machine's CPUs.
     */
    @Test
    void reportRefusesMachineFiguresTheRuleOrTheMachineCannotGive() throws Exception {
        finishedExperiment(true);
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        String good = Files.readString(csv);
        String row = good.lines().skip(1).findFirst().orElseThrow();
        int other = ResultsCsv.HEADER.indexOf("other_cpus");
        String[] fields = row.split(",", -1);
        fields[other] = "1.5";
        Files.writeString(csv, good.replace(row, String.join(",", fields)));
        CliRun.of("report", dir.toString()).assertOneLineUserError(csv + " line 2: labelled quiet but other_cpus 1.5");
        fields[ResultsCsv.HEADER.indexOf("machine")] = "busy";
        fields[other] = "5.0";
        Files.writeString(csv, good.replace(row, String.join(",", fields)));
        CliRun.of("report", dir.toString(), "--include-busy").assertOneLineUserError(
                csv + " line 2: other_cpus 5.0 is more than the machine's 2 CPUs (machine_cpus)");
        fields[other] = "1.5";
        Files.writeString(csv, good.replace(row, String.join(",", fields)));
        assertEquals(0, CliRun.of("report", dir.toString(), "--include-busy").status(), "busy, and possible");
    }

    /** Issue 24: report merged a folder whose lock named a live process. */
    @Test
    void reportRefusesAFolderARunningExperimentIsWriting() throws Exception {
        finishedExperiment(true);
        Process owner = new ProcessBuilder("sleep", "60").start();
        try {
            Files.writeString(dir.resolve(FolderLock.FILE_NAME), owner.pid() + "\n");
            CliRun.of("report", dir.toString())
                    .assertOneLineUserError("is being written by a running rtaware experiment (pid " + owner.pid());
            CliRun.of("report", dir.toString(), "--out", dir.resolveSibling(dir.getFileName() + "-merged").toString())
                    .assertOneLineUserError("is being written by a running rtaware experiment (pid " + owner.pid());
        } finally {
            owner.destroyForcibly().waitFor();
        }
        assertEquals(0, CliRun.of("report", dir.toString()).status(), "reported once the writer is gone");
    }
}
