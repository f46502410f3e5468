package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.experiment.report.ExperimentReport;
import io.rtaware.experiment.report.MapBackground;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ExperimentRunnerTest {

    @TempDir
    Path dir;

    private final ByteArrayOutputStream progressBytes = new ByteArrayOutputStream();
    private final List<List<String>> started = new ArrayList<>();

    private ExperimentRunner runner(List<PeriodSet> sets, int runs, String scenario) {
        ExperimentPlan plan = new ExperimentPlan(sets, runs, new RunConditions(scenario, 20, 7, null));
        JvmRunCommand fake = JvmRunCommand.ofCurrentProcess(FakeRun.class.getName());
        RunCommand recording = args -> {
            started.add(args);
            return fake.commandLine(args);
        };
        ProgressBar bar = new ProgressBar(new PrintStream(progressBytes, true, StandardCharsets.UTF_8), false,
                System::nanoTime, 18);
        return new ExperimentRunner(plan, recording, dir, bar);
    }

    private static List<PeriodSet> twoSets() {
        return List.of(ExperimentSets.paper().get(0), ExperimentSets.paper().get(3));
    }

    @Test
    void runsInterleavedInFreshJvmsAndRecordsEveryRun() throws Exception {
        List<RunResult> rows = runner(twoSets(), 2, "paper-room").run();
        assertEquals(4, rows.size());
        assertEquals(List.of("1/1", "2/1", "1/2", "2/2"), rows.stream().map(r -> r.set() + "/" + r.run()).toList());
        assertEquals(List.of("--scenario", "paper-room", "--periods", "waypoint=10ms,obstacle=10ms,occupancy=10ms,planner=10ms",
                "--time-scale", "20", "--seed", "7", "--robot-seed", "4", "--out", dir.resolve("runs/set1-run1").toString(), "--quiet"),
                started.get(0));
        assertEquals("8", started.get(2).get(started.get(2).indexOf("--seed") + 1));
        RunResult r = rows.get(1);
        assertEquals("completed", r.outcome());
        assertEquals(250 + 350 / 20.0 + 2.5, r.runTimeS(), 1e-9);
        assertEquals(4, r.tasks().size());
        assertEquals(2000, r.tasks().get("waypoint").releases());
        assertEquals(300.0, r.tasks().get("occupancy").execP99Us(), 1e-9);
        assertEquals(607.0, r.tasks().get("obstacle").maxSafePeriodMs(), "the reaction rule's bound from the advice");
        assertEquals(null, r.tasks().get("planner").maxSafePeriodMs(), "only reaction items give a bound");
        assertEquals(42.0, r.tasks().get("waypoint").maxSafePeriodMs(), "a report written before issue 34");
        assertEquals(java.util.Map.of("obstacle", 1L, "waypoint", 2L, "stop", 0L), r.mediatorCycles());
        assertEquals(27L, r.tasks().get("occupancy").skipped(), "54 misses, half of them skipped");
        assertTrue(Files.exists(dir.resolve("runs/set2-run2/trajectory.csv")));
        String progress = progressBytes.toString(StandardCharsets.UTF_8);
        assertTrue(progress.contains("4/4"), progress);
        assertTrue(progress.contains("running set 2 (Set 4) run 2"), progress);
        assertTrue(progress.contains("last: set 2 run 1 completed"), progress);
        assertTrue(progress.contains("ETA"), progress);
    }

    @Test
    void eachRowCarriesWhenItsRunWasMadeAndTheReadingsOfTheCheckBeforeIt() throws Exception {
        // A wall clock that moves 90 s at every reading: the runner reads it once before and once
        // after each run, so run k starts at 180 (k - 1) s and ends 90 s later.
        long[] reads = {0};
        Clock stepping = new Clock() {
            @Override
            public ZoneId getZone() {
                return ZoneOffset.UTC;
            }

            @Override
            public Clock withZone(ZoneId zone) {
                return this;
            }

            @Override
            public Instant instant() {
                return Instant.parse("2026-11-28T02:00:00.250Z").plusSeconds(90 * reads[0]++);
            }
        };
        MachineCheck.Reading quiet = new MachineCheck.Reading(new MachineVerdict(MachineVerdict.QUIET,
                List.of("other processes used 0.03 of 2 CPUs"), "load 0.2 at start"), 0.03, 0.25, 0.2);
        QuietGate gate = new QuietGate(() -> quiet, s -> { }, System::nanoTime, 0, false);
        runner(List.of(ExperimentSets.paper().get(0)), 2, "paper-room").clock(stepping).quietGate(gate).run();
        List<String> lines = Files.readAllLines(dir.resolve(ResultsCsv.FILE_NAME));
        List<String> header = ResultsCsv.split(lines.get(0));
        List<String> second = ResultsCsv.split(lines.get(2));
        assertEquals("2026-11-28T02:03:00.250Z", second.get(header.indexOf("started_utc")));
        assertEquals("2026-11-28T02:04:30.250Z", second.get(header.indexOf("ended_utc")));
        assertEquals(List.of("0.03", "0.25", "0.2", "quiet"), List.of(second.get(header.indexOf("check_other_cpus")),
                second.get(header.indexOf("check_steal_pct")), second.get(header.indexOf("check_load")),
                second.get(header.indexOf("machine_before_run"))));
        RunResult read = ResultsCsv.read(dir.resolve(ResultsCsv.FILE_NAME)).get(0);
        assertEquals(new RunTimes(Instant.parse("2026-11-28T02:00:00.250Z"), Instant.parse("2026-11-28T02:01:30.250Z")),
                read.times());
        assertEquals(0.03, read.machine().checkOtherCpus());
        // A run that left no report (an error row) keeps the check it was admitted on too.
        RunResult error = RunResult.error(1, 3, read.periods(), read.conditions())
                .withMachine(RunMachine.NOT_RECORDED.withCheck(new QuietGate.Passage("busy", 12, "r", 0.4, 0.0, 1.5)));
        ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), error);
        RunMachine back = ResultsCsv.read(dir.resolve(ResultsCsv.FILE_NAME)).get(2).machine();
        assertEquals(List.of("busy", 12.0, 0.4, 0.0, 1.5), List.of(back.beforeRun(), back.waitedS(), back.checkOtherCpus(),
                back.checkStealPct(), back.checkLoad()));
        // ... so the stated rule applies to it: a run that left no report counts as quiet when its check was.
        RunResult quietError = RunResult.error(1, 4, read.periods(), read.conditions())
                .withMachine(RunMachine.NOT_RECORDED.withCheck(new QuietGate.Passage("quiet", 0, "r", 0.01, 0.0, 0.2)));
        ResultsCsv.append(dir.resolve(ResultsCsv.FILE_NAME), quietError);
        assertTrue(ExperimentConditions.countsAsQuiet(ResultsCsv.read(dir.resolve(ResultsCsv.FILE_NAME)).get(3)));
    }

    @Test
    void withRecordingEachRunIsAskedToRecordIntoItsOwnFolder() throws Exception {
        runner(List.of(ExperimentSets.paper().get(0)), 2, "paper-room").recordEachRun(true).run();
        for (int run = 1; run <= 2; run++) {
            List<String> args = started.get(run - 1);
            assertEquals(dir.resolve("runs/set1-run" + run).resolve(ExperimentRunner.RECORDING_FILE).toString(),
                    args.get(args.indexOf("--record") + 1));
        }
    }

    @Test
    void rerunningIntoTheSameFolderSkipsRunsAlreadyThere() throws Exception {
        runner(twoSets(), 1, "paper-room").run();
        String before = Files.readString(dir.resolve(ResultsCsv.FILE_NAME));
        started.clear();
        List<RunResult> rows = runner(twoSets(), 2, "paper-room").run();
        assertEquals(2, started.size(), "only the two new runs are started");
        assertEquals(4, rows.size());
        assertTrue(Files.readString(dir.resolve(ResultsCsv.FILE_NAME)).startsWith(before));
    }

    @Test
    void refusesAFolderMadeWithOtherSettings() throws Exception {
        runner(twoSets(), 1, "paper-room").run();
        ExperimentInputException e = assertThrows(ExperimentInputException.class,
                () -> runner(List.of(ExperimentSets.paper().get(1), ExperimentSets.paper().get(3)), 1, "paper-room").run());
        assertTrue(e.getMessage().contains("was made with periods 10/10/10/10"), e.getMessage());
        e = assertThrows(ExperimentInputException.class, () -> runner(twoSets(), 1, "other-room").run());
        assertTrue(e.getMessage().contains("scenario paper-room"), e.getMessage());
    }

    @Test
    void exitStatusTwoStopsWithTheRunsOwnMessage() {
        ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> runner(twoSets(), 1, "reject").run());
        assertTrue(e.getMessage().contains("unknown scenario 'reject'"), e.getMessage());
        assertEquals(1, e.getMessage().lines().count());
    }

    @Test
    void aCrashedRunIsRecordedAsErrorAndLeftOutOfStatistics() throws Exception {
        List<RunResult> rows = runner(twoSets(), 1, "crash").run();
        assertEquals(2, rows.size());
        assertEquals("error", rows.get(0).outcome());
        assertFalse(rows.get(0).measured());
        assertTrue(Double.isNaN(rows.get(0).runTimeS()));
        ExperimentSummary s = ExperimentSummary.of(rows, ExperimentProfile.fromResults(rows));
        assertEquals(0, s.sets().get(0).runTimeS().n());
        assertNull(s.sets().get(0).misses().get("all").missPct());
        assertFalse(s.tTests().get("run_time_s").get(0).test().applicable());
    }

    @Test
    void interruptKillsTheRunAndKeepsTheFolderValid() throws Exception {
        Path slowDir = dir.resolve("slow");
        ExperimentRunner r = new ExperimentRunner(new ExperimentPlan(List.of(ExperimentSets.paper().get(0)), 2,
                new RunConditions("slow", 20, 7, null)), JvmRunCommand.ofCurrentProcess(FakeRun.class.getName()), slowDir,
                new ProgressBar(new PrintStream(progressBytes, true, StandardCharsets.UTF_8), false, System::nanoTime, 1));
        AtomicReference<List<RunResult>> result = new AtomicReference<>();
        Thread t = new Thread(() -> {
            try {
                result.set(r.run());
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
        t.start();
        Thread.sleep(1500);
        long startNs = System.nanoTime();
        r.interrupt();
        t.join(20_000);
        assertFalse(t.isAlive());
        assertTrue((System.nanoTime() - startNs) / 1e9 < 15, "the child was stopped, not waited for");
        assertTrue(r.interrupted());
        assertEquals(List.of(), result.get());
        assertFalse(Files.exists(slowDir.resolve(ResultsCsv.FILE_NAME)));
    }

    @Test
    void reportFromCsvAloneGivesTheSameNumbers() throws Exception {
        runner(ExperimentSets.paper(), 3, "paper-room").run();
        ExperimentSummary first = ExperimentReport.render(dir, MapBackground.none());
        JsonNode json1 = ReportDocument.mapper().readTree(dir.resolve("summary.json").toFile());
        for (String f : List.of("report.md", "report.html", "fig7-task-misses.png", "fig8-set-misses.png",
                "runtime-box.png", "distance-box.png", "trajectories.png", "fig7-task-misses.svg")) {
            assertTrue(Files.size(dir.resolve(f)) > 1000, f);
            Files.delete(dir.resolve(f));
        }
        Files.delete(dir.resolve("summary.json"));
        // only results.csv (and the trajectories) remain: re-render
        ExperimentSummary second = ExperimentReport.render(dir, MapBackground.none());
        assertEquals(first, second);
        assertEquals(json1, ReportDocument.mapper().readTree(dir.resolve("summary.json").toFile()));
        ExperimentSummary.SetSummary set4 = second.sets().get(3);
        assertEquals("Set 4", set4.name());
        assertEquals(3, set4.completed());
        // seeds 7, 8, 9 -> (seed % 3) * 2.5 = 2.5, 5, 0 on top of 250 + 350 / 20
        assertEquals(250 + 17.5 + 2.5, set4.runTimeS().mean(), 1e-9);
        assertEquals(2.5, set4.runTimeS().sd(), 1e-9);
        assertEquals(10, second.tTests().get("run_time_s").size());
        String md = Files.readString(dir.resolve("report.md"));
        assertTrue(md.contains("| Set 4 | 100 | 50 | 100 | 100 | 3 of 3 | 3 completed | 270.00 | 2.50 | 276.97 | 5.17 |"), md);
        assertTrue(Files.readString(dir.resolve("report.html")).contains("data:image/png;base64,"));
    }
}
