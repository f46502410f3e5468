package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.RtawareCli;
import io.rtaware.core.testing.Requires;
import io.rtaware.core.testing.Waits;
import io.rtaware.ros2.graph.QosProfile;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Names;
import io.rtaware.ros2.graph.Ros2Node;
import io.rtaware.ros2msg.DiagnosticArrayCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2MessageType;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.TransformMessages;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.PlanarPose;
import io.rtaware.zenoh.NativeZenohLayer;
import io.rtaware.zenoh.SampleBuffer;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohMailbox;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --export} seen from another Zenoh peer, as a developer's machine would see it: the test
 * listens on a loopback endpoint, {@code bench} and {@code run} connect to it with
 * {@code --export-zenoh}, and the test subscribes the ROS 2 topics the README names.
 */
@Timeout(180)
class ExportEndToEndTest {

    @TempDir
    Path dir;

    private String endpoint;
    private Ros2Context watcher;
    private Ros2Node node;
    private ZenohMailbox mailbox;

    @BeforeEach
    @Requires(NativeZenohLayer.class)
    void listen() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            endpoint = "tcp/127.0.0.1:" + s.getLocalPort();
        }
        watcher = Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(endpoint)), 0);
        node = watcher.createNode("/", "export_watcher");
        mailbox = watcher.session().newMailbox(256);
    }

    @AfterEach
    void close() throws Exception {
        if (watcher != null) {
            watcher.close();
        }
    }

    private static CompletableFuture<Integer> command(String... args) {
        return CompletableFuture.supplyAsync(() -> RtawareCli.execute(args));
    }

    @Test
    void benchExportsTaskHealthOnDiagnostics() throws Exception {
        DiagnosticArrayCodec codec = new DiagnosticArrayCodec();
        node.subscribe("/diagnostics", codec.type(), QosProfile.defaults(), mailbox, 0);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream savedErr = System.err;
        PrintStream savedOut = System.out;
        DiagnosticArray array = new DiagnosticArray(16, 16);
        List<String> names = new ArrayList<>();
        int status;
        try {
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            CompletableFuture<Integer> bench = command("bench", "--export", "--export-zenoh", endpoint, "--tasks", "2",
                    "--period", "10ms", "--work", "0", "--duration", "4s", "--quiet");
            SampleBuffer sample = new SampleBuffer(1 << 16, 64);
            assertEquals(ZenohMailbox.Take.SAMPLE, mailbox.take(TimeUnit.SECONDS.toNanos(60), sample),
                    "a DiagnosticArray from bench --export");
            byte[] bytes = new byte[sample.payloadLength()];
            sample.payload().get(0, bytes);
            codec.decode(new CdrReader().wrap(bytes, 0, bytes.length), new Ros2Header(), array);
            for (int i = 0; i < array.count(); i++) {
                names.add(array.status(i).name.toString());
            }
            List<String> tokens = watcher.session().livelinessKeys("@ros2_lv/0/**", 2000);
            assertTrue(tokens.stream().anyMatch(t -> t.contains("/MP/%/%/rtaware_monitor/%diagnostics/"
                    + "diagnostic_msgs::msg::dds_::DiagnosticArray_/RIHS01_")), "the publisher's token in " + tokens);
            status = bench.get(60, TimeUnit.SECONDS);
        } finally {
            System.setErr(savedErr);
            System.setOut(savedOut);
        }
        String text = err.toString(StandardCharsets.UTF_8);
        assertEquals(0, status, text);
        assertTrue(names.containsAll(List.of("rtaware: task t1", "rtaware: task t2", "rtaware: key t1.out",
                "rtaware: key t2.out")), "one status per task and per key: " + names);
        assertTrue(text.contains("/diagnostics, /statistics (no key of this run has a ROS 2 type"),
                "says what it exports: " + text);
    }

    @Test
    void runExportsTheKeysWithRos2TypesUnderRtawareAndTheRep105Frames() throws Exception {
        List<String> topics = List.of("/rtaware/laser", "/rtaware/odometry", "/rtaware/motor", "/rtaware/map",
                "/rtaware/path", "/diagnostics", "/tf", "/tf_static", "/statistics");
        List<Ros2MessageType> types = List.of(Ros2Types.LASER_SCAN, Ros2Types.ODOMETRY, Ros2Types.TWIST,
                Ros2Types.OCCUPANCY_GRID, Ros2Types.PATH, new DiagnosticArrayCodec().type(), Ros2Types.TF_MESSAGE,
                Ros2Types.TF_MESSAGE, Ros2Types.METRICS_MESSAGE);
        for (int i = 0; i < topics.size(); i++) {
            mailbox.subscribe(Ros2Names.topicKey(0, topics.get(i), types.get(i).ddsTypeName(), types.get(i).typeHash()), i);
        }
        Path scenario = Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
        PrintStream savedErr = System.err;
        PrintStream savedOut = System.out;
        Set<String> seen = new HashSet<>();
        Set<String> frames = new HashSet<>();
        int status;
        try {
            System.setErr(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            CompletableFuture<Integer> run = command("run", "--export", "--export-zenoh", endpoint, "--scenario",
                    scenario.toString(), "--time-scale", "4", "--quiet", "--out", dir.resolve("run").toString());
            SampleBuffer sample = new SampleBuffer(1 << 16, 64);
            Waits.until(() -> {
                ZenohMailbox.Take took = mailbox.take(TimeUnit.MILLISECONDS.toNanos(100), sample);
                if (took == ZenohMailbox.Take.SAMPLE || took == ZenohMailbox.Take.TOO_LARGE) {
                    String topic = topics.get(sample.channel());
                    seen.add(topic);
                    if (took == ZenohMailbox.Take.SAMPLE && topic.startsWith("/tf")) {
                        frames.addAll(transforms(topic, sample));
                    }
                }
                return seen.size() == topics.size();
            }, Duration.ofSeconds(60), () -> "a sample on every exported topic; seen " + seen);
            status = run.get(120, TimeUnit.SECONDS);
        } finally {
            System.setErr(savedErr);
            System.setOut(savedOut);
        }
        assertEquals(0, status);
        assertEquals(Set.copyOf(topics), seen, "the topics the README names, with their ROS 2 types");
        assertEquals(Set.of("/tf: odom -> base_link", "/tf_static: base_link -> laser"), frames,
                "the REP 105 frames of the exported data, with no map -> odom (nothing localizes)");
    }

    /** @return "topic: parent -> child" of each transform of a TFMessage */
    private static List<String> transforms(String topic, SampleBuffer sample) {
        byte[] bytes = new byte[sample.payloadLength()];
        sample.payload().get(0, bytes);
        CdrReader in = new CdrReader().wrap(bytes, 0, bytes.length);
        Ros2Header header = new Ros2Header();
        StringBuilder child = new StringBuilder();
        List<String> out = new ArrayList<>();
        for (int i = TransformMessages.count(in); i > 0; i--) {
            TransformMessages.read(in, header, child, new PlanarPose());
            out.add(topic + ": " + header.frameId + " -> " + child);
        }
        return out;
    }
}
