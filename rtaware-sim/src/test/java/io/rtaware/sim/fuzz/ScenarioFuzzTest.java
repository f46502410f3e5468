package io.rtaware.sim.fuzz;

import com.code_intelligence.jazzer.junit.FuzzTest;
import io.rtaware.sim.map.MapException;
import io.rtaware.sim.scenario.ScenarioException;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

/**
 * Coverage-guided fuzzing of the scenario loader with the bytes of a user's scenario file
 * (issue 24), beside a small valid map ({@code map.yaml}, 8 x 6 cells): a malformed scenario may
 * only be refused with a {@link ScenarioException} or {@link MapException} (one line to the user);
 * any other throwable is a finding. Without {@code JAZZER_FUZZ=1} it replays the corpus in
 * {@code ScenarioFuzzTestInputs/}, seeded from the paper's course and the tests' scenarios.
 */
class ScenarioFuzzTest {

    private static Path dir;
    private static Path scenario;

    @BeforeAll
    static void writeTheMap() throws IOException {
        dir = Files.createTempDirectory("scenario-fuzz");
        MapFuzzTest.writeSmallMap(dir);
        scenario = dir.resolve("scenario.yaml");
    }

    @AfterAll
    static void removeTheMap() throws IOException {
        try (var files = Files.list(dir)) {
            for (Path f : files.toList()) {
                Files.delete(f);
            }
        }
        Files.delete(dir);
    }

    @FuzzTest(maxDuration = "20s")
    void loadingAScenarioThrowsNothingButScenarioErrors(byte[] input) throws IOException {
        Files.write(scenario, input);
        try {
            ScenarioLoader.load(scenario);
        } catch (ScenarioException | MapException refused) {
            // the user's one line
        }
    }
}
