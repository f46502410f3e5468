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
        PeriodSet set = ExperimentSets.paper().get(3);
        ExperimentPlan plan = new ExperimentPlan(List.of(set), 1, new RunConditions("paper-room", 20, 5, null));
        if (withPlanFile) {
            PlanFile.write(dir, plan);
        }
        ExperimentProfile.of(plan, "test machine").write(dir);
        ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), new RunResult(1, 1, set, plan.conditions(), "completed",
                12.0, 0.2, 3.0, 0, 4, 4, Map.of()).withMachine(new io.rtaware.experiment.RunMachine("quiet", "", 0.01, 0,
                0.2, 0.2, 0.1, Double.NaN, "quiet", 0)));
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
}
