package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What run prints besides its summary: warnings about the course before it starts, and no java.util.logging lines. */
class RunConsoleTest {

    @TempDir
    Path dir;

    @Test
    void aWaypointOffTheMapIsWarnedAboutAndTheRunStillGoesWithoutJulLines() throws Exception {
        Path resources = Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/paper-room.yaml")).toURI()).getParent();
        Files.copy(resources.resolve("paper-room.yaml"), dir.resolve("paper-room.yaml"));
        Files.copy(resources.resolve("paper-room.pgm"), dir.resolve("paper-room.pgm"));
        Path scenario = Files.writeString(dir.resolve("off-map.yaml"), "map: paper-room.yaml\nstart: {x: 0.8, y: 0.8, yaw: 0.0}\n"
                + "waypoints:\n  - {x: 40.0, y: 0.8}\ngoal_tolerance_m: 0.3\ntime_limit_s: 3\n");
        List<LogRecord> published = new ArrayList<>();
        Handler recorder = new Handler() {
            @Override
            public void publish(LogRecord record) {
                synchronized (published) {
                    published.add(record);
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger root = Logger.getLogger("");
        root.addHandler(recorder);
        CliRun r;
        try {
            r = CliRun.of("run", "--scenario", scenario.toString(), "--time-scale", "20", "--out", dir.resolve("out").toString());
        } finally {
            root.removeHandler(recorder);
        }
        assertEquals(0, r.status(), "the run goes and ends at its time limit: " + r);
        assertTrue(r.err().lines().findFirst().orElse("").startsWith("rtaware run: warning: waypoint 1 (40.00, 0.80) lies off the map"),
                "warned before the run: " + r.err());
        assertTrue(r.out().contains("run: timeout"), r.out());
        synchronized (published) {
            assertEquals(List.of(), published.stream().map(p -> p.getLoggerName() + ": " + p.getMessage()).toList(),
                    "no record reaches the console's JUL handlers");
        }
    }
}
