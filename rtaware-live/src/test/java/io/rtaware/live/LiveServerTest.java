package io.rtaware.live;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.SteppedThreads;
import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.testing.LiveThreads;
import io.rtaware.core.testing.ThreadAllocation;
import io.rtaware.core.testing.Waits;
import io.rtaware.core.time.Clock;
import io.rtaware.core.time.ManualClock;
import io.rtaware.core.time.SystemClock;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The live view's endpoints over real loopback sockets. */
class LiveServerTest {

    private static final long MS = 1_000_000L;
    private static final ObjectMapper JSON = new ObjectMapper();
    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : toClose) {
            c.close();
        }
    }

    private LiveServer server() throws IOException {
        LiveServer server = new LiveServer(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0),
                "<html>page</html>".getBytes(StandardCharsets.UTF_8));
        toClose.add(server);
        return server;
    }

    private HttpResponse<String> get(int port, String path) throws Exception {
        return http.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + path))
                .timeout(Duration.ofSeconds(5)).build(), HttpResponse.BodyHandlers.ofString());
    }

    /** A running two-task chain with a bench view (tasks and keys, no map). */
    private LiveView benchView(Monitor monitor) throws IOException {
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        LiveView view = LiveView.start(LiveOptions.loopback(0), monitor,
                new PrintStream(printed, true, StandardCharsets.UTF_8));
        toClose.add(view);
        assertEquals("live view: http://127.0.0.1:" + view.port() + "/" + System.lineSeparator(),
                printed.toString(StandardCharsets.UTF_8), "the URL on a line of its own");
        return view;
    }

    private static Monitor chain() {
        return chain(new SystemClock(), 200_000, 100_000);
    }

    private static Monitor chain(Clock clock, long spinANs, long spinBNs) {
        return Monitor.builder(clock)
                .task("a", Schedule.periodic(Duration.ofMillis(10)), new ChainTask("a", spinANs, null))
                .task("b", Schedule.periodic(Duration.ofMillis(20)), new ChainTask("b", spinBNs, "a"))
                .build();
    }

    /** The latest snapshot the publisher has served that {@code wanted} accepts (it publishes on wall time). */
    private JsonNode awaitSnapshot(int port, Predicate<JsonNode> wanted, String what) throws Exception {
        JsonNode[] latest = {null};
        Waits.until(() -> {
            HttpResponse<String> response = get(port, "/snapshot.json");
            assertEquals(200, response.statusCode());
            assertEquals("application/json", response.headers().firstValue("Content-Type").orElse(""));
            latest[0] = JSON.readTree(response.body());
            return wanted.test(latest[0]);
        }, Duration.ofSeconds(30), () -> what + "; latest " + latest[0]);
        return latest[0];
    }

    /**
     * The view's threads (its publisher, the HTTP thread that served a request) are observers:
     * the allocation check of {@code bench --live --fail-on-alloc} does not count them as the
     * framework's threads on the per-release path, whatever the browser makes them allocate.
     */
    @Test
    void theViewsThreadsAreOffTheTasksPerReleasePath() throws Exception {
        Set<Thread> before = Set.of(LiveThreads.all());
        LiveView view = benchView(chain());
        assertEquals(200, get(view.port(), "/snapshot.json").statusCode());

        List<Thread> ours = Arrays.stream(LiveThreads.all())
                .filter(t -> !before.contains(t) && t.getName().startsWith(ThreadNames.PREFIX)).toList();
        assertTrue(ours.size() >= 2, "the publisher and a thread that served the request: " + ours);
        assertEquals(List.of(), ours.stream().filter(ThreadAllocation::onReleasePath).toList(),
                "counted as the framework's on the per-release path");
    }

    /**
     * The tasks' real threads on stepped world time (issue 38: it slept three publish periods of
     * wall time, then asserted that something had run): 100 ms of world time are exactly ten
     * cycles of 'a' and five of 'b', and the snapshot says so.
     */
    @Test
    void snapshotJsonHasTasksAndKeys() throws Exception {
        ManualClock clock = new ManualClock();
        Monitor monitor = chain(clock, 0, 0);
        LiveView view = benchView(monitor);
        monitor.start();
        try {
            new SteppedThreads(monitor, clock).runUntil(100 * MS); // the clock stays at 90 ms, a's tenth release
            JsonNode s = awaitSnapshot(view.port(), snapshot -> snapshot.path("time_s").asDouble() == 0.09,
                    "a snapshot at the stepped world time");
            assertEquals(SnapshotBuilder.SCHEMA, s.path("schema").asText());
            assertEquals("bench", s.path("kind").asText());
            assertEquals("running", s.path("state").asText());
            assertTrue(s.path("seq").asLong() >= 1);
            assertEquals(10, s.path("tasks").get(0).path("runs").asLong(), "a: releases at 0, 10, ..., 90 ms");
            assertEquals(5, s.path("tasks").get(1).path("runs").asLong(), "b: releases at 0, 20, ..., 80 ms");
            JsonNode a = s.path("tasks").get(0);
            assertEquals("a", a.path("name").asText());
            assertEquals(10.0, a.path("period_ms").asDouble());
            for (String field : new String[] {"releases", "runs", "misses", "miss_pct", "recent_miss_pct", "skipped",
                    "stale_runs", "errors", "recent_exec_p99_ms", "recent_exec_p99_of_period"}) {
                assertTrue(a.has(field), "task field " + field + " in " + a);
            }
            assertFalse(a.has("exec_p99_ms"), "the p99 of the latest runs is not named as the report's whole-run p99");
            assertEquals(256, s.path("recent_exec_runs").asInt(), "the runs the recent p99 covers, as the core keeps them");
            assertEquals(TaskCounters.RECENT_EXEC_RUNS, s.path("recent_exec_runs").asInt());
            assertEquals(0.0, a.path("recent_exec_p99_ms").asDouble(), "a cycle takes no world time here: " + a);
            JsonNode key = s.path("keys").get(0);
            assertEquals("a.out", key.path("name").asText());
            assertEquals("a", key.path("producer").asText());
            assertEquals("b", key.path("consumers").get(0).asText());
            assertEquals(50.0, key.path("consumer_rate_hz").asDouble(), "b runs every 20 ms");
            assertEquals(100.0, key.path("nyquist_rate_hz").asDouble(), "twice the consumer's rate");
            assertTrue(key.has("recent_rate_hz") && key.has("rate_hz"));
            assertFalse(s.has("run") || s.has("robot"), "a bench snapshot has no map or robot");
        } finally {
            view.finish(monitor.stop(), null);
        }
        JsonNode end = JSON.readTree(get(view.port(), "/snapshot.json").body());
        assertEquals("finished", end.path("state").asText());
        assertEquals("rtaware.report/1", end.path("final").path("report").path("schema").asText(),
                "the final snapshot carries the report");
        String page = get(view.port(), "/").body();
        assertTrue(page.contains("rtaware live view"), "the page is served");
        assertFalse(page.contains("latest 128"), "issue 34: the note said 128 cycles where the core keeps 256");
        assertTrue(page.contains("latest ${s.recent_exec_runs} runs"), "the note takes the count from the snapshot");
        assertTrue(page.contains("exec p99 (whole run)") && page.contains("recent exec p99"),
                "the two p99s of one task have two names");
        assertTrue(page.contains("course time") && page.contains(">elapsed <"), "and so have the two times");
    }

    @Test
    void eventStreamDeliversSnapshots() throws Exception {
        Monitor monitor = chain();
        LiveView view = benchView(monitor);
        monitor.start();
        try {
            HttpResponse<Stream<String>> response = http.send(HttpRequest.newBuilder(
                    URI.create("http://127.0.0.1:" + view.port() + "/events")).build(), HttpResponse.BodyHandlers.ofLines());
            assertEquals(200, response.statusCode());
            assertTrue(response.headers().firstValue("Content-Type").orElse("").startsWith("text/event-stream"));
            List<JsonNode> events = new ArrayList<>();
            Iterator<String> lines = response.body().iterator();
            while (events.size() < 3 && lines.hasNext()) {
                String line = lines.next();
                if (line.startsWith("data: ")) {
                    events.add(JSON.readTree(line.substring("data: ".length())));
                }
            }
            response.body().close();
            assertEquals(3, events.size());
            assertNotEquals(events.get(0).path("seq").asLong(), events.get(2).path("seq").asLong(), "new snapshots");
            assertTrue(events.get(2).path("tasks").get(0).path("runs").asLong()
                    > events.get(0).path("tasks").get(0).path("runs").asLong(), "the numbers move");
        } finally {
            monitor.stop();
        }
    }

    @Test
    void unknownPathsAre404AndOtherMethods405() throws Exception {
        LiveServer server = server();
        server.putResource("/world.png", "image/png", new byte[] {1, 2, 3});
        assertEquals(404, get(server.port(), "/nope").statusCode());
        assertEquals(404, get(server.port(), "/snapshot.json/x").statusCode());
        assertEquals(200, get(server.port(), "/world.png?g=3").statusCode(), "query strings are ignored");
        assertEquals("<html>page</html>", get(server.port(), "/").body());
        HttpResponse<String> post = http.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + server.port() + "/"))
                .POST(HttpRequest.BodyPublishers.ofString("x")).build(), HttpResponse.BodyHandlers.ofString());
        assertEquals(405, post.statusCode());
    }

    @Test
    void aClientThatNeverReadsHoldsAtMostOneSnapshot() throws Exception {
        LiveServer server = server();
        try (Socket stuck = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            stuck.setReceiveBufferSize(4096);
            request(stuck, "/events");
            awaitClients(server, 1);
            byte[] snapshot = new byte[256 * 1024];
            Arrays.fill(snapshot, (byte) 'x');
            // A publish that waited for the browser would wait for ever: the bound only ends such a test.
            assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
                for (int i = 0; i < 2_000; i++) { // 512 MB offered to a client that reads nothing
                    server.publish(snapshot);
                    assertTrue(server.bufferedBytes() <= snapshot.length, "one slot per client: " + server.bufferedBytes());
                }
            }, "publish never waits for the browser");
            assertEquals(1, server.eventClients());
        }
    }

    @Test
    void aClientThatDisconnectsIsRemoved() throws Exception {
        LiveServer server = server();
        server.publish("{\"seq\":1}".getBytes(StandardCharsets.UTF_8));
        try (Socket client = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            request(client, "/events");
            InputStream in = client.getInputStream();
            String received = readUntil(in, "data: {\"seq\":1}");
            assertTrue(received.contains("text/event-stream"), received);
            assertEquals(1, server.eventClients());
        }
        int[] seq = {1};
        Waits.until(() -> { // a write to the closed socket finds it closed
            seq[0]++;
            server.publish(("{\"seq\":" + seq[0] + "}").getBytes(StandardCharsets.UTF_8));
            return server.eventClients() == 0;
        }, Duration.ofSeconds(10), "the closed client dropped");
        assertEquals(1, server.eventClientsEver());
    }

    @Test
    void concurrentConnectsNeverExceedTheEventClientCap() throws Exception {
        LiveServer server = server();
        int clients = 8 * LiveServer.MAX_EVENT_CLIENTS;
        List<Socket> sockets = new ArrayList<>();
        try {
            for (int i = 0; i < clients; i++) {
                Socket s = new Socket(InetAddress.getLoopbackAddress(), server.port());
                s.setSoTimeout(10_000);
                sockets.add(s);
            }
            for (Socket s : sockets) { // a burst: the server's handler threads admit them concurrently
                request(s, "/events");
            }
            int admitted = 0;
            int refused = 0;
            for (Socket s : sockets) {
                String status = readUntil(s.getInputStream(), "\r\n");
                if (status.startsWith("HTTP/1.1 200")) {
                    admitted++;
                } else if (status.startsWith("HTTP/1.1 503")) {
                    refused++;
                }
            }
            assertEquals(LiveServer.MAX_EVENT_CLIENTS, admitted, "admitted streams (all stay open)");
            assertEquals(clients - LiveServer.MAX_EVENT_CLIENTS, refused, "refused with 503");
            assertEquals(LiveServer.MAX_EVENT_CLIENTS, server.eventClientsEver());
        } finally {
            for (Socket s : sockets) {
                s.close();
            }
        }
    }

    private static void request(Socket socket, String path) throws IOException {
        socket.getOutputStream().write(("GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
                .getBytes(StandardCharsets.US_ASCII));
        socket.getOutputStream().flush();
    }

    private static String readUntil(InputStream in, String marker) throws IOException {
        StringBuilder seen = new StringBuilder();
        int b;
        while (seen.indexOf(marker) < 0 && (b = in.read()) >= 0) {
            seen.append((char) b);
        }
        return seen.toString();
    }

    private static void awaitClients(LiveServer server, int n) throws Exception {
        Waits.until(() -> server.eventClients() >= n, Duration.ofSeconds(10), () -> n + " event clients, "
                + server.eventClients() + " seen");
        assertEquals(n, server.eventClients());
    }
}
