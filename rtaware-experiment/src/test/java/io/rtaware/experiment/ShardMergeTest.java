package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.experiment.report.ExperimentReport;
import io.rtaware.experiment.report.MapBackground;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Shards made in separate folders and merged give the report of the same plan made in one folder. */
class ShardMergeTest {

    @TempDir
    Path dir;

    private static final List<PeriodSet> SETS = List.of(ExperimentSets.paper().get(0), ExperimentSets.paper().get(3),
            ExperimentSets.paper().get(4));

    private void make(Path out, Shard shard, long seed) throws Exception {
        ExperimentPlan plan = new ExperimentPlan(SETS, 3, new RunConditions("paper-room", 20, seed, null), shard);
        ExperimentProfile.of(plan, "test machine").write(Files.createDirectories(out));
        new ExperimentRunner(plan, JvmRunCommand.ofCurrentProcess(FakeRun.class.getName()), out,
                new ProgressBar(new PrintStream(OutputStream.nullOutputStream()), false, System::nanoTime, 18)).run();
    }

    @Test
    void mergedShardsEqualTheUnshardedExperiment() throws Exception {
        Path whole = dir.resolve("whole");
        make(whole, Shard.WHOLE, 7);
        Path a = dir.resolve("a");
        Path b = dir.resolve("b");
        make(a, new Shard(1, 2), 7);
        make(b, new Shard(2, 2), 7);
        assertEquals(5, ResultsCsv.read(a.resolve(ResultsCsv.FILE_NAME)).size());
        assertEquals(4, ResultsCsv.read(b.resolve(ResultsCsv.FILE_NAME)).size());

        Path merged = dir.resolve("merged");
        assertEquals(9, ExperimentMerge.merge(List.of(b, a), merged).size());
        assertEquals(withoutTimes(whole), withoutTimes(merged), "the same rows, each with the times it was made");
        ExperimentSummary expected = ExperimentReport.render(whole, MapBackground.none());
        ExperimentSummary actual = ExperimentReport.render(merged, MapBackground.none());
        assertEquals(expected, actual);
        JsonNode x = ReportDocument.mapper().readTree(whole.resolve(ExperimentReport.SUMMARY_FILE).toFile());
        JsonNode y = ReportDocument.mapper().readTree(merged.resolve(ExperimentReport.SUMMARY_FILE).toFile());
        assertEquals(x, y);
        assertTrue(Files.exists(merged.resolve("runs/set3-run3/trajectory.csv")));
        assertEquals(Shard.WHOLE, PlanFile.read(merged).orElseThrow().shard());
    }

    /** results.csv's lines without started_utc and ended_utc, which differ between two makings of a run. */
    private static List<List<String>> withoutTimes(Path folder) throws Exception {
        int started = ResultsCsv.HEADER.indexOf("started_utc");
        int ended = ResultsCsv.HEADER.indexOf("ended_utc");
        List<List<String>> lines = new java.util.ArrayList<>();
        for (String line : Files.readAllLines(folder.resolve(ResultsCsv.FILE_NAME))) {
            List<String> fields = new java.util.ArrayList<>(ResultsCsv.split(line));
            fields.set(started, "");
            fields.set(ended, "");
            lines.add(fields);
        }
        return lines;
    }

    @Test
    void foldersOfDifferentPlansOrTheSameRunTwiceAreRefused() throws Exception {
        Path a = dir.resolve("a");
        Path b = dir.resolve("b");
        Path other = dir.resolve("other");
        make(a, new Shard(1, 2), 7);
        make(b, new Shard(2, 2), 7);
        make(other, new Shard(2, 2), 8);
        assertRefused(List.of(a, other), dir.resolve("m1"), "different plans");
        assertRefused(List.of(a, a), dir.resolve("m2"), "is in both");
        assertRefused(List.of(a, b), a, "is one of the folders");
        Path fewer = dir.resolve("fewer");
        ExperimentPlan plan = new ExperimentPlan(SETS.subList(0, 2), 3, new RunConditions("paper-room", 20, 7, null),
                new Shard(2, 2));
        Files.createDirectories(fewer);
        PlanFile.write(fewer, plan);
        Files.writeString(fewer.resolve(ResultsCsv.FILE_NAME), String.join(",", ResultsCsv.HEADER) + "\n");
        assertRefused(List.of(a, fewer), dir.resolve("m3"), "different plans");
        assertTrue(Files.notExists(dir.resolve("m1").resolve(ResultsCsv.FILE_NAME)));
    }

    private static void assertRefused(List<Path> dirs, Path out, String expected) {
        ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> ExperimentMerge.merge(dirs, out));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
        assertEquals(1, e.getMessage().lines().count(), e.getMessage());
    }
}
