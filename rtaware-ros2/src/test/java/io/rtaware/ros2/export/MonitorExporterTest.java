package io.rtaware.ros2.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2.NativeZenohAssumption;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Names;
import io.rtaware.ros2msg.DiagnosticArrayCodec;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.DiagnosticStatus;
import io.rtaware.zenoh.SampleBuffer;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohMailbox;
import java.net.ServerSocket;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The exporter seen from another Zenoh session: keys as ROS 2 types, health on /diagnostics. */
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

    @Test
    void keysAndHealthReachAnotherSession() throws Exception {
        NativeZenohAssumption.require();
        Monitor monitor = Monitor.builder(new ManualClock())
                .task("scanner", Schedule.periodic(Duration.ofMillis(10)), new Scanner()).build();
        monitor.startStepped().runUntil(100 * MS);
        String endpoint;
        try (ServerSocket s = new ServerSocket(0)) {
            endpoint = "tcp/127.0.0.1:" + s.getLocalPort();
        }
        try (Ros2Context viewer = Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(endpoint)), 0)) {
            ZenohMailbox mailbox = viewer.session().newMailbox(64);
            mailbox.subscribe(Ros2Names.topicKey(0, "/diagnostics", Ros2Types.DIAGNOSTIC_ARRAY.ddsTypeName(),
                    Ros2Types.DIAGNOSTIC_ARRAY.typeHash()), 0);
            mailbox.subscribe(Ros2Names.topicKey(0, "/rtaware/laser", Ros2Types.LASER_SCAN.ddsTypeName(),
                    Ros2Types.LASER_SCAN.typeHash()), 1);
            Ros2Context exporting = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(endpoint)), 0);
            DiagnosticArray array = new DiagnosticArray(8, 16);
            LaserScan scan = new LaserScan();
            boolean sawArray = false;
            boolean sawScan = false;
            try (MonitorExporter exporter = MonitorExporter.start(monitor, exporting,
                    List.of(new ExportedKey<>(RobotKeys.LASER, new LaserScanCodec(), "laser")), List.of(), 10)) {
                assertEquals("/rtaware/laser", exporter.topics().get("laser"));
                SampleBuffer sample = new SampleBuffer(1 << 16, 64);
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                while (!(sawArray && sawScan) && System.nanoTime() < deadline) {
                    if (mailbox.take(TimeUnit.MILLISECONDS.toNanos(100), sample) != ZenohMailbox.Take.SAMPLE) {
                        continue;
                    }
                    byte[] bytes = new byte[sample.payloadLength()];
                    sample.payload().get(0, bytes);
                    CdrReader in = new CdrReader().wrap(bytes, 0, bytes.length);
                    if (sample.channel() == 0) {
                        new DiagnosticArrayCodec().decode(in, new Ros2Header(), array);
                        sawArray = true;
                    } else {
                        new LaserScanCodec().decode(in, new Ros2Header(), scan);
                        sawScan = true;
                    }
                }
            }
            assertTrue(sawArray && sawScan, "a DiagnosticArray and a LaserScan arrived");
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
