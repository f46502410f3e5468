package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Key;
import io.rtaware.record.encode.TimingTypes;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.TransformMessages;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.value.PlanarPose;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The times in a recording, on exact values: header stamps when the data was measured (the
 * robot's own timestamps on the run's clock) or when it was committed, {@code /clock} ticks on
 * simulated time, and the type hashes of rtaware's own types on their channels.
 */
class RecordingTimeTest {

    private static final Key<LaserScan> LASER = Key.of("laser", LaserScan.class, () -> new LaserScan(8));
    private static final Key<Odometry> ODOMETRY = Key.of("odometry", Odometry.class, Odometry::new);
    private static final Key<VelocityCommand> MOTOR = Key.of("motor", VelocityCommand.class, VelocityCommand::new);
    /** Unix-epoch ns of world time 0. */
    private static final long OFFSET_NS = 1_764_000_000_000_000_000L;
    /** The world time at which the robot's clock read 0. */
    private static final long ORIGIN_NS = 5_000_000_000L;
    private static final long MS = 1_000_000L;

    @TempDir
    Path dir;

    private record Msg(String topic, long logTimeNs, byte[] data) {
    }

    private RecordingPlan plan() {
        return new RecordingPlan().topic("laser", "/scan", "laser").topic("odometry", "/odom", "odom")
                .topic("motor", "/cmd_vel", "base_link").transformsFrom("odometry", "odom", "base_link")
                .staticTransform("base_link", "laser", 0, 0, 0).logTimeOffsetNs(OFFSET_NS).worldStartNs(0);
    }

    /** Records a scan measured at robot time 1.25 s and odometry sampled at 1.3 s, both committed at 1.5 s. */
    private List<Msg> record(Path file, RecordingPlan plan, Map<String, McapChannel> channels) throws IOException {
        RunRecorder recorder = new RunRecorder(file, List.of("t"), List.of(List.of()), List.of(LASER, ODOMETRY, MOTOR),
                plan);
        LaserScan scan = new LaserScan(8);
        scan.maxRangeM = 5;
        scan.serverTimeS = 1.25;
        scan.setCount(2);
        recorder.commit(0, 1, 1500 * MS, scan);
        Odometry odometry = new Odometry();
        odometry.xM = 2;
        odometry.yM = -1;
        odometry.yawRad = 0.5;
        odometry.serverTimeS = 1.3;
        recorder.commit(1, 1, 1500 * MS, odometry);
        recorder.commit(2, 1, 1600 * MS, new VelocityCommand());
        recorder.cycle(0, RunRecorder.OK, 1000 * MS, 1000 * MS, 1035 * MS, 0, null);
        RecordingStats stats = recorder.finish();
        assertNull(stats.error());
        List<Msg> messages = new ArrayList<>();
        McapReader.open(file).read(new McapVisitor() {
            @Override
            public void channel(McapChannel channel) {
                channels.put(channel.topic(), channel);
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                byte[] data, int offset, int length) {
                messages.add(new Msg(channel.topic(), logTimeNs, Arrays.copyOfRange(data, offset, offset + length)));
            }
        });
        return messages;
    }

    private static Msg only(List<Msg> messages, String topic) {
        List<Msg> found = messages.stream().filter(m -> m.topic().equals(topic)).toList();
        assertEquals(1, found.size(), topic);
        return found.get(0);
    }

    private static long scanStampNs(List<Msg> messages) {
        byte[] data = only(messages, "/scan").data();
        Ros2Header header = new Ros2Header();
        new LaserScanCodec().decode(new CdrReader().wrap(data, 0, data.length), header, new LaserScan(8));
        return header.stampNs;
    }

    private static long odometryStampNs(List<Msg> messages) {
        byte[] data = only(messages, "/odom").data();
        Ros2Header header = new Ros2Header();
        new OdometryCodec("base_link").decode(new CdrReader().wrap(data, 0, data.length), header, new Odometry());
        return header.stampNs;
    }

    /** @return the stamp of the one transform of the one /tf message */
    private static long transformStampNs(List<Msg> messages) {
        byte[] data = only(messages, "/tf").data();
        CdrReader in = new CdrReader().wrap(data, 0, data.length);
        assertEquals(1, TransformMessages.count(in), "one transform");
        Ros2Header header = new Ros2Header();
        StringBuilder child = new StringBuilder();
        PlanarPose pose = new PlanarPose();
        TransformMessages.read(in, header, child, pose);
        assertEquals("odom -> base_link", header.frameId + " -> " + child, "the odometry's transform");
        assertEquals(2.0, pose.xM, "x of the odometry");
        return header.stampNs;
    }

    @Test
    void scansAndOdometryAreStampedWhenTheRobotMeasuredThem() throws IOException {
        Map<String, McapChannel> channels = new HashMap<>();
        List<Msg> messages = record(dir.resolve("measured.mcap"), plan().robotClockOriginNs(ORIGIN_NS), channels);
        assertEquals(OFFSET_NS + 1500 * MS, only(messages, "/scan").logTimeNs(), "logged at the commit");
        assertEquals(OFFSET_NS + ORIGIN_NS + 1250 * MS, scanStampNs(messages),
                "stamped at the robot's 1.25 s: world time 6.25 s");
        assertEquals(OFFSET_NS + ORIGIN_NS + 1300 * MS, odometryStampNs(messages), "the pose's sample time");
        assertEquals(OFFSET_NS + ORIGIN_NS + 1300 * MS, transformStampNs(messages), "/tf stamped as its odometry");
    }

    @Test
    void withoutTheRobotsClockEveryHeaderIsStampedAtItsCommit() throws IOException {
        Map<String, McapChannel> channels = new HashMap<>();
        List<Msg> messages = record(dir.resolve("committed.mcap"), plan(), channels);
        assertEquals(OFFSET_NS + 1500 * MS, scanStampNs(messages), "the commit's time");
        assertEquals(OFFSET_NS + 1500 * MS, odometryStampNs(messages), "the commit's time");
        assertEquals(OFFSET_NS + 1500 * MS, transformStampNs(messages), "the commit's time");
    }

    @Test
    void clockTicksOnSimulatedTimeCarryTheirLogTimesInOrderUpToTheLastMessage() throws IOException {
        Map<String, McapChannel> channels = new HashMap<>();
        List<Msg> messages = record(dir.resolve("clock.mcap"), plan().clock(500 * MS), channels);
        List<Long> ticks = new ArrayList<>();
        for (Msg m : messages) {
            if (m.topic().equals("/clock")) {
                CdrReader in = new CdrReader().wrap(m.data(), 0, m.data().length);
                long clockNs = in.readInt32() * 1_000_000_000L + (in.readInt32() & 0xffffffffL);
                assertEquals(m.logTimeNs(), clockNs, "a tick carries its log time");
                ticks.add(clockNs);
            }
        }
        assertEquals(List.of(OFFSET_NS, OFFSET_NS + 500 * MS, OFFSET_NS + 1000 * MS, OFFSET_NS + 1500 * MS), ticks,
                "every 500 ms from the start, up to the last message (1.6 s)");
        for (int i = 1; i < messages.size(); i++) {
            assertTrue(messages.get(i).logTimeNs() >= messages.get(i - 1).logTimeNs(), "log-time order at " + i);
        }
        McapChannel clock = channels.get("/clock");
        assertEquals(Ros2Types.CLOCK.typeHash(), clock.metadata().get("topic_type_hash"));
        assertTrue(clock.metadata().get("offered_qos_profiles").contains("reliability: 2\n  durability: 2"),
                "best effort, volatile, as rclcpp's ClockQoS: " + clock.metadata());
    }

    @Test
    void rtawaresOwnTypesDeclareTheirTypeHashes() throws IOException {
        Map<String, McapChannel> channels = new HashMap<>();
        record(dir.resolve("hashes.mcap"), plan(), channels);
        assertEquals(TimingTypes.TASK_CYCLE.typeHash(), channels.get("/rtaware/timing/t").metadata().get("topic_type_hash"));
        assertEquals(TimingTypes.MONITOR_EVENT.typeHash(), channels.get("/rtaware/events").metadata().get("topic_type_hash"));
        assertEquals(TimingTypes.STATE_JSON.typeHash(), channels.get("/rtaware/state/laser").metadata()
                .get("topic_type_hash"));
        assertTrue(channels.get("/clock") == null, "no /clock on wall time");
        assertTrue(channels.get("/tf_static") != null, "/tf_static as planned");
    }
}
