package io.rtaware.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.report.TaskReport;
import io.rtaware.record.TaskCycleMessage;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.replay.ExactReplay;
import io.rtaware.replay.Recording;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The example runs as a user would run it: real threads, a real file, a replay of every task. */
class ThreeTaskControllerTest {

    @Test
    void theControllerRunsRecordsAndReplaysEveryTaskIdentically(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("three-tasks.mcap");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        ThreeTaskController.Outcome outcome = ThreeTaskController.run(file, Duration.ofMillis(500),
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));

        assertTrue(Files.size(file) > 0, "the recording was written");
        assertEquals(0, outcome.recording().dropped(), "the recorder kept every value and cycle");
        assertEquals(List.of("pose", "slow", "drive"), outcome.replays().stream().map(ExactReplay.TaskResult::name).toList());
        Recording recording = Recording.load(McapReader.open(file), file);
        for (ExactReplay.TaskResult r : outcome.replays()) {
            TaskReport task = outcome.report().task(r.name());
            List<Recording.Cycle> records = recording.tasks().get(r.name()).cycles();
            List<TaskCycleMessage> skips = records.stream().map(Recording.Cycle::message)
                    .filter(m -> m.outcome().equals("skipped")).toList();
            assertTrue(task.runs() > 0, r.name() + " ran");
            // On a loaded machine a late task skips releases; each run of skipped releases is one
            // record, which the replay counts as a cycle beside the runs.
            assertEquals(task.skipped(), skips.stream().mapToLong(TaskCycleMessage::skippedReleases).sum(),
                    r.name() + ": every skipped release was recorded");
            assertEquals(task.runs() + skips.size(), r.cycles(), r.name() + ": every run and skip record was replayed");
            assertEquals(r.cycles(), r.identical(), r.name() + ": a function of its inputs replays identically: " + r);
        }
        String printed = out.toString(StandardCharsets.UTF_8);
        assertTrue(printed.startsWith("ran "), printed);
        assertTrue(printed.contains("replayed drive"), printed);
        assertTrue(err.toString(StandardCharsets.UTF_8).lines().count() <= 1,
                "at most the one line that says real-time threads are not permitted: " + err);
    }
}
