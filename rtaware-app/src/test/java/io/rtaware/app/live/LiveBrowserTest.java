package io.rtaware.app.live;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.app.RtawareCli;
import io.rtaware.core.testing.Requires;
import io.rtaware.core.testing.Waits;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * End to end in a real browser: {@code rtaware run --live} on the short course, headless
 * Chromium (driven over the DevTools protocol) opens the page, the robot and the task rows
 * appear, the numbers move, each task's strip chart draws its lateness and execution time on a
 * minute-long time axis, the header shows the machine verdict so far, a screenshot is saved to
 * {@code target/live-view.png}, and after the run the page shows the final summary, which names
 * the figures by odometry and those in truth, also on reload. Needs {@link HeadlessChromium}.
 */
class LiveBrowserTest {

    private static final Pattern URL = Pattern.compile("live view: (http://127\\.0\\.0\\.1:\\d+/)");

    @TempDir
    Path dir;

    @Test
    @Requires(HeadlessChromium.class)
    void pageShowsTheRobotAndLiveTaskRowsThenTheFinalSummary() throws Exception {
        Path chromium = Cdp.chromium();
        Path scenario = Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
        ByteArrayOutputStream stdout = new ByteArrayOutputStream();
        PrintStream saved = System.out;
        System.setOut(new PrintStream(stdout, true, StandardCharsets.UTF_8));
        CompletableFuture<Integer> run;
        try {
            // Time scale 2: slow enough (about 8 s of wall time) for two looks while the robot drives.
            // On a thread of its own: the common pool has one thread on a 2-core machine, and the
            // HttpClient's WebSocket handshake (JDK 25) must not wait behind a whole run there.
            run = new CompletableFuture<>();
            CompletableFuture<Integer> result = run;
            Thread runner = new Thread(() -> {
                try {
                    result.complete(RtawareCli.execute("run", "--scenario", scenario.toString(),
                            "--time-scale", "2", "--out", dir.resolve("run").toString(), "--quiet", "--seed", "7",
                            "--live", "--live-linger", "12s"));
                } catch (RuntimeException | Error e) {
                    result.completeExceptionally(e);
                }
            }, "rtaware-run-under-test");
            runner.setDaemon(true);
            runner.start();
            String url = awaitUrl(stdout, run);
            try (Cdp browser = Cdp.launch(chromium, dir.resolve("profile"))) {
                browser.navigate(url);
                JsonNode first = awaitPage(browser, "rows.length === 6 && document.getElementById('map').dataset.robot",
                        15);
                assertEquals("running", first.path("state").asText(), "the run is still going: " + first);
                // the next looks until the runs have grown and the robot has moved (or the run ended)
                JsonNode second = awaitPage(browser, "(rows.length > 0 && [...rows].reduce((n, r) => n + "
                        + "Number(r.children[2].textContent), 0) > " + first.path("runs").asLong()
                        + " && document.getElementById('map').dataset.robot !== '" + first.path("robot").asText() + "')"
                        + " || document.getElementById('state').textContent === 'finished'", 30);
                assertTrue(second.path("runs").asLong() > first.path("runs").asLong()
                        || second.path("state").asText().equals("finished"),
                        "task runs grow between two looks: " + first + " then " + second);
                assertTrue(!second.path("robot").asText().equals(first.path("robot").asText())
                        || second.path("state").asText().equals("finished"), "the robot moves: " + first + " " + second);
                JsonNode strips = awaitPage(browser, "[...document.querySelectorAll('#strips canvas')]"
                        + ".filter(c => Number(c.dataset.points) > 0).length === 6", 15);
                assertEquals(6, strips.path("strips").size(), "a strip chart per task: " + strips);
                strips.path("strips").forEach(c -> {
                    assertTrue(c.path("points").asInt() > 0, "lateness and execution time drawn: " + c);
                    assertEquals("0-60", c.path("axis").asText(), "a minute of world time from the start: " + c);
                });
                assertTrue(strips.path("machine").asText().matches("(quiet|busy|disturbed|unknown) \\(over \\d+ s\\)"),
                        "the machine verdict so far in the header: " + strips);
                assertTrue(!strips.path("machineReason").asText().isEmpty(), "and its reasons: " + strips);
                Path shot = Path.of("target", "live-view.png");
                Files.createDirectories(shot.getParent());
                browser.screenshot(shot);
                assertTrue(Files.size(shot) > 10_000, "a screenshot of the page");

                JsonNode end = awaitPage(browser, "!!latest && latest.state === 'finished'", 60);
                assertTrue(end.path("final").asText().contains("Final summary"), "final summary shown: " + end);
                browser.call("Page.reload", null);
                JsonNode reloaded = awaitPage(browser, "!!latest && latest.state === 'finished' && rows.length === 6", 15);
                assertTrue(reloaded.path("final").asText().contains("completed"), "the same summary after a reload: "
                        + reloaded);
                assertTrue(reloaded.path("final").asText().matches("(?s).*completed: finish reached by odometry; "
                        + "\\d+\\.\\d\\d m from it in truth.*"), "the ending says what is true: " + reloaded);
                assertTrue(reloaded.path("final").asText().contains("1 of 1 by odometry"),
                        "the final page says which figures are the robot's belief: " + reloaded);
                assertTrue(reloaded.path("final").asText().contains("in truth (ground truth)")
                        && reloaded.path("final").asText().contains("in truth (the simulator's contacts)"),
                        "and which are measured in truth: " + reloaded);
                browser.screenshot(Path.of("target", "live-view-final.png"));
            }
            assertEquals(0, run.get(60, TimeUnit.SECONDS), "exit status; output:\n" + stdout);
        } finally {
            System.setOut(saved);
        }
    }

    private static String awaitUrl(ByteArrayOutputStream stdout, CompletableFuture<Integer> run) throws Exception {
        Matcher m = URL.matcher("");
        Waits.until(() -> m.reset(stdout.toString(StandardCharsets.UTF_8)).find() || run.isDone(),
                Duration.ofSeconds(60), () -> "a 'live view: URL' line; output:\n" + stdout);
        if (!m.reset(stdout.toString(StandardCharsets.UTF_8)).find()) {
            throw new AssertionError("the run ended without a 'live view: URL' line; output:\n" + stdout);
        }
        return m.group(1);
    }

    private static final String STATE = "(() => { const rows = document.querySelectorAll('#tasks tbody tr');"
            + " let runs = 0; rows.forEach(r => runs += Number(r.children[2].textContent));"
            + " return { rows: rows.length, runs: runs, state: document.getElementById('state').textContent,"
            + " robot: document.getElementById('map').dataset.robot || '',"
            + " strips: [...document.querySelectorAll('#strips canvas')].map(c => ({ points: Number(c.dataset.points),"
            + " misses: Number(c.dataset.misses), axis: c.dataset.axis })),"
            + " machine: document.getElementById('machine').textContent,"
            + " machineReason: document.getElementById('machineReason').textContent,"
            + " final: document.getElementById('final').style.display === 'block'"
            + " ? document.getElementById('final').innerText : '' }; })()";

    private static JsonNode state(Cdp browser) throws Exception {
        return browser.eval(STATE);
    }

    private static JsonNode awaitPage(Cdp browser, String condition, int seconds) throws Exception {
        String test = "(() => { const rows = document.querySelectorAll('#tasks tbody tr');"
                + " try { return !!(" + condition + "); } catch (e) { return false; } })()";
        Waits.until(() -> browser.eval(test).asBoolean(), Duration.ofSeconds(seconds),
                () -> "the page to meet " + condition);
        return state(browser);
    }
}
