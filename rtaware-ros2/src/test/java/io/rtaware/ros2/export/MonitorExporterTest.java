package io.rtaware.ros2.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.testing.Requires;
import io.rtaware.core.testing.Waits;
import io.rtaware.core.time.ManualClock;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Names;
import io.rtaware.ros2msg.DiagnosticArrayCodec;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.MetricsMessageCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.DiagnosticStatus;
import io.rtaware.ros2msg.value.MetricsMessage;
import io.rtaware.zenoh.NativeZenohLayer;
import io.rtaware.zenoh.SampleBuffer;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohMailbox;
import java.net.ServerSocket;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The exporter seen from another Zenoh session: keys as ROS 2 types, health on /diagnostics, the
 * topic statistics on /statistics.
 */
@Timeout(60)
class MonitorExporterTest {

    private static final long MS = 1_000_000L;

    /** Commits a scan of 3 beams each cycle. */
    private static final class Scanner implements Task {
        private Output<LaserScan> out;

        @Override
        public void initialize(TaskSetup setup) {
            out = setup.produce(RobotKeys.LASER);
        }

        @Override
        public void execute(long nowNs) {
            LaserScan s = out.value();
            s.setCount(3);
            s.rangesM[1] = 2.5f;
            s.maxRangeM = 4;
            s.maxAngleRad = 1;
            out.publish();
        }
    }

    /** A monitor of the scanner at 10 ms on a manual clock, not started. */
    private static Monitor scanning(ManualClock clock) {
        return Monitor.builder(clock).task("scanner", Schedule.periodic(Duration.ofMillis(10)), new Scanner()).build();
    }

    private static String loopbackEndpoint() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            return "tcp/127.0.0.1:" + s.getLocalPort();
        }
    }

    /** Takes samples until {@code done} says so (fails after 20 s, naming {@code awaited}); each sample's CDR to {@code sampled}. */
    private static void take(ZenohMailbox mailbox, java.util.function.BooleanSupplier done, String awaited,
                             java.util.function.ObjIntConsumer<CdrReader> sampled) throws Exception {
        SampleBuffer sample = new SampleBuffer(1 << 16, 64);
        Waits.until(() -> {
            if (done.getAsBoolean()) {
                return true;
            }
            if (mailbox.take(TimeUnit.MILLISECONDS.toNanos(100), sample) == ZenohMailbox.Take.SAMPLE) {
                byte[] bytes = new byte[sample.payloadLength()];
                sample.payload().get(0, bytes);
                sampled.accept(new CdrReader().wrap(bytes, 0, bytes.length), sample.channel());
            }
            return false;
        }, Duration.ofSeconds(20), awaited);
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void keysAndHealthReachAnotherSession() throws Exception {
        ManualClock clock = new ManualClock();
        Monitor monitor = scanning(clock);
        String endpoint = loopbackEndpoint();
        try (Ros2Context viewer = Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(endpoint)), 0)) {
            ZenohMailbox mailbox = viewer.session().newMailbox(64);
            mailbox.subscribe(Ros2Names.topicKey(0, "/diagnostics", Ros2Types.DIAGNOSTIC_ARRAY.ddsTypeName(),
                    Ros2Types.DIAGNOSTIC_ARRAY.typeHash()), 0);
            mailbox.subscribe(Ros2Names.topicKey(0, "/rtaware/laser", Ros2Types.LASER_SCAN.ddsTypeName(),
                    Ros2Types.LASER_SCAN.typeHash()), 1);
            Ros2Context exporting = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(endpoint)), 0);
            DiagnosticArray array = new DiagnosticArray(8, 16);
            LaserScan scan = new LaserScan();
            boolean[] saw = new boolean[2];
            try (MonitorExporter exporter = MonitorExporter.start(monitor, exporting,
                    List.of(new ExportedKey<>(RobotKeys.LASER, new LaserScanCodec(), "laser")), List.of(), 10)) {
                monitor.startStepped().runUntil(100 * MS);
                assertEquals("/rtaware/laser", exporter.topics().get("laser"));
                take(mailbox, () -> saw[0] && saw[1], "the keys' and the health's samples", (in, channel) -> {
                    if (channel == 0) { // the first arrays may come before the run: wait for one after it
                        new DiagnosticArrayCodec().decode(in, new Ros2Header(), array);
                        DiagnosticStatus task = find(array, "rtaware: task scanner");
                        saw[0] = task != null && Long.parseLong(value(task, "releases")) >= 10;
                    } else {
                        new LaserScanCodec().decode(in, new Ros2Header(), scan);
                        saw[1] = true;
                    }
                });
            }
            assertTrue(saw[0] && saw[1], "a DiagnosticArray and a LaserScan arrived");
            assertEquals(3, scan.count());
            assertEquals(2.5f, scan.rangesM[1]);
            DiagnosticStatus task = find(array, "rtaware: task scanner");
            assertNotNull(task, "a status for the task");
            assertEquals("10.000", value(task, "period_ms"));
            assertTrue(Long.parseLong(value(task, "releases")) >= 10, "releases: " + value(task, "releases"));
            DiagnosticStatus key = find(array, "rtaware: key laser");
            assertNotNull(key, "a status for the key");
            assertEquals("published on /rtaware/laser", key.message.toString());
            assertEquals("scanner", value(key, "producer"));
        }
        monitor.stop();
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void statisticsOfEveryTaskAndKeyReachAnotherSessionOnceTheirSecondIsOver() throws Exception {
        ManualClock clock = new ManualClock();
        Monitor monitor = scanning(clock);
        String endpoint = loopbackEndpoint();
        Map<String, MetricsMessage> firstSecond = new HashMap<>();
        long published;
        try (Ros2Context viewer = Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(endpoint)), 0)) {
            ZenohMailbox mailbox = viewer.session().newMailbox(64);
            mailbox.subscribe(Ros2Names.topicKey(0, "/statistics", Ros2Types.METRICS_MESSAGE.ddsTypeName(),
                    Ros2Types.METRICS_MESSAGE.typeHash()), 0);
            Ros2Context exporting = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(endpoint)), 0);
            try (MonitorExporter exporter = MonitorExporter.start(monitor, exporting, List.of(), List.of(), 10)) {
                monitor.startStepped().runUntil(1500 * MS); // the first second is over; the scanner is past it
                take(mailbox, () -> firstSecond.size() == 6, "six statistics sources of the first second", (in, channel) -> {
                    MetricsMessage m = new MetricsMessage(5);
                    new MetricsMessageCodec().decode(in, new Ros2Header(), m);
                    firstSecond.putIfAbsent(m.measurementSourceName + " " + m.metricsSource, m);
                });
                // The exporter counts a message after publishing it: the viewer may hold the sixth first.
                Waits.until(() -> exporter.statisticsPublished() >= 6, Duration.ofSeconds(10),
                        "the exporter counting the sixth statistics message it published");
                published = exporter.statisticsPublished();
                assertEquals(0, exporter.statisticsLost());
            }
        }
        monitor.stop();
        assertEquals(Set.of("scanner release_lateness", "scanner execution_time", "scanner input_age",
                "scanner deadline_misses", "laser message_period", "laser message_age"), firstSecond.keySet());
        assertEquals(6, published, "the first second, and not the half second after it");
        MetricsMessage periods = firstSecond.get("laser message_period");
        assertEquals(1_000_000_000L, periods.windowStopNs - periods.windowStartNs);
        assertEquals("ms", periods.unit.toString());
        assertEquals(10.0, periods.valueOf(MetricsMessage.AVERAGE), "commits every 10 ms");
        assertEquals(99.0, periods.valueOf(MetricsMessage.SAMPLE_COUNT), "100 commits in the second, 99 periods");
        MetricsMessage misses = firstSecond.get("scanner deadline_misses");
        assertEquals(100.0, misses.valueOf(MetricsMessage.SAMPLE_COUNT), "releases at 0, 10, ..., 990 ms");
        assertEquals(0.0, misses.valueOf(MetricsMessage.MAXIMUM));
        assertEquals(0.0, firstSecond.get("scanner execution_time").valueOf(MetricsMessage.MAXIMUM),
                "a stepped cycle takes no world time");
        assertEquals(0.0, firstSecond.get("laser message_age").valueOf(MetricsMessage.SAMPLE_COUNT), "no consumer");
        assertTrue(Double.isNaN(firstSecond.get("laser message_age").valueOf(MetricsMessage.AVERAGE)));
    }

    private static DiagnosticStatus find(DiagnosticArray array, String name) {
        for (int i = 0; i < array.count(); i++) {
            if (array.status(i).name.toString().equals(name)) {
                return array.status(i);
            }
        }
        return null;
    }

    private static String value(DiagnosticStatus s, String key) {
        for (int i = 0; i < s.valueCount(); i++) {
            if (s.key(i).toString().equals(key)) {
                return s.value(i).toString();
            }
        }
        return null;
    }
}
