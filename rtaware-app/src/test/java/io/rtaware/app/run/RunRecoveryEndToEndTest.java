package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import io.rtaware.core.testing.Waits;
import io.rtaware.core.time.Clock;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import io.rtaware.sim.world.World;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 12 end to end, on real threads against an external simulator ({@code run --player}):
 * a simulator killed and restarted during the run, and a proxy that starts sending NaN poses.
 * Events are triggered by conditions on the simulated world, not by sleeps; the assertions are
 * on the outcome and the report, not on timing.
 */
@Timeout(120)
class RunRecoveryEndToEndTest {

    private static final double TIME_SCALE = 10;
    private static final long SEED = 7;

    @TempDir
    Path dir;

    private Scenario scenario;
    private Path scenarioFile;

    private PlayerSimServer startSim(int port) throws Exception {
        scenarioFile = Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
        scenario = ScenarioLoader.load(scenarioFile);
        return SimCommandSupport.start(scenario, Clock.forTimeScale(TIME_SCALE), ServerConfig.defaults(port), SEED, SEED);
    }

    private CompletableFuture<Integer> runAgainst(int port, Path out) {
        return CompletableFuture.supplyAsync(() -> RtawareCli.execute("run", "--player", "127.0.0.1:" + port,
                "--scenario", scenarioFile.toString(), "--time-scale", Double.toString(TIME_SCALE), "--out",
                out.toString(), "--quiet", "--seed", Long.toString(SEED)));
    }

    private static void await(BooleanSupplier condition, String what) throws Exception {
        Waits.until(condition::getAsBoolean, Duration.ofSeconds(60), what);
    }

    private static double distanceFromStart(PlayerSimServer sim, Scenario scenario) {
        return sim.withWorld(w -> Math.hypot(w.xM() - scenario.start().xM(), w.yM() - scenario.start().yM()));
    }

    @Test
    void aRestartedSimulatorIsReconnectedByTheRefereeAndTheReportShowsTheGap() throws Exception {
        PlayerSimServer first = startSim(0);
        int port = first.port();
        Path out = dir.resolve("restart");
        PrintStream saved = System.out;
        System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        PlayerSimServer second = null;
        int status;
        try {
            CompletableFuture<Integer> run = runAgainst(port, out);
            await(() -> distanceFromStart(first, scenario) > 0.4, "the robot drove 0.4 m");
            first.close();
            // The port stays taken but answers nothing Player-like until both of the run's
            // clients (controller and referee) have tried to reconnect twice.
            AtomicInteger attempts = new AtomicInteger();
            try (ServerSocket dead = new ServerSocket()) {
                dead.setReuseAddress(true);
                dead.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
                Thread refuser = new Thread(() -> {
                    while (true) {
                        try (Socket s = dead.accept()) {
                            attempts.incrementAndGet();
                        } catch (Exception closed) {
                            return;
                        }
                    }
                });
                refuser.setDaemon(true);
                refuser.start();
                await(() -> attempts.get() >= 4, "four reconnection attempts");
            }
            second = startSim(port);
            status = run.get(90, TimeUnit.SECONDS);
        } finally {
            System.setOut(saved);
            if (second != null) {
                second.close();
            }
        }
        JsonNode report = new ObjectMapper().readTree(out.resolve("report.json").toFile());
        JsonNode runSection = report.path("run");
        assertEquals(0, status, "run section: " + runSection);
        assertEquals("completed", runSection.path("outcome").asText(), "run section: " + runSection);
        JsonNode gaps = runSection.path("ground_truth_gaps");
        JsonNode gap = null;
        double lostS = 0;
        for (JsonNode g : gaps) {
            assertFalse(g.path("open").asBoolean(), "ground truth came back: " + gaps);
            double lengthS = g.path("to_s").asDouble() - g.path("from_s").asDouble();
            lostS += lengthS;
            if (lengthS > 1.0 && (gap == null || lengthS > gap.path("to_s").asDouble() - gap.path("from_s").asDouble())) {
                gap = g;
            }
        }
        assertTrue(gap != null, "a gap of more than 1 s while the simulator was down: " + runSection);
        double toS = gap.path("to_s").asDouble();
        double runTimeS = runSection.path("run_time_s").asDouble();
        assertEquals(runTimeS - lostS, runSection.path("ground_truth_covered_s").asDouble(), 0.002 * (1 + gaps.size()));
        assertTrue(runSection.path("distance_to_finish_m").isNumber(), "a fresh final pose is measured");
        List<String> rows = Files.readAllLines(out.resolve("trajectory.csv"));
        double lastT = Double.parseDouble(rows.get(rows.size() - 1).split(",")[0]);
        assertTrue(lastT > toS, "the trajectory goes on after the gap: last sample at " + lastT + " s, gap " + gap);
        assertTrue(Files.readString(out.resolve("report.md")).contains("ground truth lost: "),
                "report.md names the gap");
        assertTrue(report.path("player").path("connects").asLong() >= 2, "the controller reconnected too");
    }

    @Test
    void nanPosesFromAProxyHaltTheRobotAndEndTheRunAsAnError() throws Exception {
        PlayerSimServer sim = startSim(0);
        Path out = dir.resolve("nan");
        PrintStream savedOut = System.out;
        PrintStream savedErr = System.err;
        ByteArrayOutputStream stderr = new ByteArrayOutputStream();
        int status;
        try (PoisoningProxy proxy = new PoisoningProxy(sim.port())) {
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(stderr, true, StandardCharsets.UTF_8));
            CompletableFuture<Integer> run = runAgainst(proxy.port(), out);
            await(() -> distanceFromStart(sim, scenario) > 0.3, "the robot drove 0.3 m");
            proxy.poison();
            status = run.get(90, TimeUnit.SECONDS);
            assertTrue(proxy.poisoned() > 0);
            await(() -> sim.withWorld(World::speedMps) == 0.0, "the simulated robot stands still");
        } finally {
            System.setOut(savedOut);
            System.setErr(savedErr);
            sim.close();
        }
        String err = stderr.toString(StandardCharsets.UTF_8);
        assertEquals(1, status, "stderr: " + err);
        JsonNode report = new ObjectMapper().readTree(out.resolve("report.json").toFile());
        JsonNode runSection = report.path("run");
        assertEquals("error", runSection.path("outcome").asText(), "run section: " + runSection);
        assertTrue(runSection.path("reason").asText().startsWith("position2d:0 sent only impossible samples"),
                runSection.path("reason").asText());
        assertTrue(runSection.path("reason").asText().contains("x = NaN"), runSection.path("reason").asText());
        long errLines = err.lines().filter(l -> l.contains("position2d:0 sent only impossible samples")).count();
        assertEquals(1, errLines, "one line names the device and the value: " + err);
        JsonNode devices = report.path("player").path("devices");
        assertTrue(devices.path("position2d:0").path("rejected_samples").asLong() > 0, "devices: " + devices);
        assertEquals(0, devices.path("laser:0").path("rejected_samples").asLong(), "devices: " + devices);
        assertTrue(report.path("player").path("fault").asText().contains("x = NaN"));
        boolean playerErrors = false;
        for (JsonNode t : report.path("tasks")) {
            playerErrors |= t.path("name").asText().equals("player") && t.path("errors").asLong() >= 1;
        }
        assertTrue(playerErrors, "the halt is counted as an error of the player task");
    }

    /**
     * Issue 24, finding 1, over the Player protocol: a laser whose every range reads 0 (blinded by
     * something against it) is an obstacle at the minimum range, which the controller turns away
     * from without driving into it, not free space it drives through.
     */
    @Test
    void aLaserReadingZeroEverywhereIsNeverDrivenInto() throws Exception {
        PlayerSimServer sim = startSim(0);
        Path out = dir.resolve("blind");
        PrintStream savedOut = System.out;
        int status;
        double drivenM;
        try (PoisoningProxy proxy = new PoisoningProxy(sim.port())) {
            proxy.blindLaser();
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            status = RtawareCli.execute("run", "--player", "127.0.0.1:" + proxy.port(), "--scenario",
                    scenarioFile.toString(), "--time-scale", Double.toString(TIME_SCALE), "--stuck-after", "20s", "--out",
                    out.toString(), "--quiet", "--seed", Long.toString(SEED));
            assertTrue(proxy.blinded() > 0, "scans were blinded");
            drivenM = distanceFromStart(sim, scenario);
        } finally {
            System.setOut(savedOut);
            sim.close();
        }
        assertEquals(0, status);
        JsonNode report = new ObjectMapper().readTree(out.resolve("report.json").toFile());
        assertEquals("stuck", report.path("run").path("outcome").asText(), report.path("run").toString());
        assertTrue(drivenM < 0.05, "the robot turned in place instead of driving: " + drivenM + " m from the start");
        assertEquals(0, report.path("player").path("devices").path("laser:0").path("rejected_samples").asLong(),
                "zeros are readings, not impossible data: " + report.path("player"));
    }
}
