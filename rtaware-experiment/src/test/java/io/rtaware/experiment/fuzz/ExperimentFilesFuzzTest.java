package io.rtaware.experiment.fuzz;

import com.code_intelligence.jazzer.junit.FuzzTest;
import io.rtaware.experiment.ExperimentInputException;
import io.rtaware.experiment.PlanFile;
import io.rtaware.experiment.ResultsCsv;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

/**
 * Coverage-guided fuzzing of what {@code experiment --resume} and {@code report} read from an
 * experiment folder (issue 24): the input is {@code plan.json}, a zero byte, then
 * {@code results.csv}. A folder that is not what it should be may only be refused with an
 * {@link ExperimentInputException} (the user's one line); any other throwable is a finding.
 * Without {@code JAZZER_FUZZ=1} it replays the corpus in {@code ExperimentFilesFuzzTestInputs/},
 * seeded from the published experiment folders.
 */
class ExperimentFilesFuzzTest {

    private static Path dir;

    @BeforeAll
    static void folder() throws IOException {
        dir = Files.createTempDirectory("experiment-fuzz");
    }

    @AfterAll
    static void removeFolder() throws IOException {
        try (var files = Files.list(dir)) {
            for (Path f : files.toList()) {
                Files.delete(f);
            }
        }
        Files.delete(dir);
    }

    @FuzzTest(maxDuration = "20s")
    void readingAPlanAndResultsThrowsNothingButInputErrors(byte[] input) throws IOException {
        int split = 0;
        while (split < input.length && input[split] != 0) {
            split++;
        }
        Files.write(dir.resolve(PlanFile.FILE_NAME), java.util.Arrays.copyOfRange(input, 0, split));
        Files.write(dir.resolve(ResultsCsv.FILE_NAME),
                java.util.Arrays.copyOfRange(input, Math.min(split + 1, input.length), input.length));
        try {
            PlanFile.read(dir);
        } catch (ExperimentInputException refused) {
            // the user's one line
        }
        try {
            ResultsCsv.readRows(dir.resolve(ResultsCsv.FILE_NAME));
        } catch (ExperimentInputException refused) {
            // the user's one line
        }
    }
}
