package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.core.data.Key;
import io.rtaware.robot.msg.GoalSet;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapSummary;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What is handed to the recorder comes back out of the file, on the planned channels. */
class RunRecorderTest {

    private static final Key<LaserScan> LASER = Key.of("laser", LaserScan.class, () -> new LaserScan(8));
    private static final Key<MotionRequest> MOTION = Key.of("motion.avoid", MotionRequest.class, MotionRequest::new);
    private static final Key<GoalSet> GOALS = Key.of("goals", GoalSet.class, () -> new GoalSet(4));

    @TempDir
    Path dir;

    private record Msg(String topic, long logTimeNs, byte[] data) {
    }

    @Test
    void recordsValuesCyclesEventsAndGroundTruth() throws IOException {
        Path file = dir.resolve("run.mcap");
        RecordingPlan plan = new RecordingPlan().topic("laser", "/scan", "base_link").metadata("scenario", "test")
                .withGroundTruth();
        RunRecorder recorder = new RunRecorder(file, List.of("avoid", "laser-task"),
                List.of(List.of("laser"), List.of()), List.of(LASER, MOTION, GOALS), plan);
        LaserScan scan = new LaserScan(8);
        scan.minAngleRad = -1;
        scan.maxAngleRad = 1;
        scan.maxRangeM = 5;
        scan.serverTimeS = 12.5;
        scan.setCount(3);
        scan.rangesM[0] = 1;
        scan.rangesM[1] = 2;
        scan.rangesM[2] = 3;
        recorder.commit(0, 1, 1_000, scan);
        MotionRequest motion = new MotionRequest();
        motion.request(0.25, -0.5);
        recorder.commit(1, 1, 2_000, motion);
        GoalSet goals = new GoalSet(4);
        goals.add(7, 1.5, 2.5);
        recorder.commit(2, 1, 2_500, goals);
        recorder.cycle(0, RunRecorder.OK, 3_000, 3_500, 5_000, 0, new long[] {1});
        recorder.cycle(0, RunRecorder.MISS, 10_000, 10_000, 30_000, 0, new long[] {1});
        recorder.cycle(1, RunRecorder.SKIPPED, 40_000, 40_000, 40_000, 2, null);
        recorder.event(RunRecorder.DEADLINE_MISS, 0, 20_000, 10_000, 20_000, true, null, null);
        recorder.groundTruth(6_000, 1, 2, 0.5);
        recorder.log(RunRecorder.ERROR_LEVEL, 7_000, "safety", "collision: the robot touched an obstacle (1 so far)");
        RecordingStats stats = recorder.finish();
        assertNull(stats.error());
        assertEquals(0, stats.dropped());
        assertEquals(11, stats.messages(), "scan + its state, motion, goals, 3 cycles, 1 event + its log line, 1 pose, "
                + "1 line of the run's own");

        McapReader reader = McapReader.open(file);
        List<Msg> messages = new ArrayList<>();
        List<Map<String, String>> metadata = new ArrayList<>();
        List<McapChannel> channels = new ArrayList<>();
        reader.read(new McapVisitor() {
            @Override
            public void channel(McapChannel channel) {
                channels.add(channel);
            }

            @Override
            public void metadata(String name, Map<String, String> entries) {
                if (name.equals("rtaware.run")) {
                    metadata.add(entries);
                } else if (name.equals(RunRecorder.STATISTICS_METADATA)) {
                    assertEquals("0", entries.get("windows"), "40 us of records: no whole second of statistics");
                } else {
                    assertEquals("rosbag2", name, "the other metadata record");
                    assertTrue(entries.get("serialized_metadata").contains("message_count: 11"), entries.toString());
                }
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                byte[] data, int offset, int length) {
                messages.add(new Msg(channel.topic(), logTimeNs, Arrays.copyOfRange(data, offset, offset + length)));
            }
        });
        assertEquals(List.of(Map.of("scenario", "test")), metadata);
        for (int i = 1; i < messages.size(); i++) {
            assertTrue(messages.get(i).logTimeNs() >= messages.get(i - 1).logTimeNs(),
                    "log-time order, handed over out of order: " + messages.get(i - 1) + " then " + messages.get(i));
        }
        assertEquals(0, stats.outOfOrder(), "all within the reorder window");
        assertEquals("ros2", reader.summary().profile());
        assertTrue(channels.stream().allMatch(c -> c.messageEncoding().equals("cdr")
                && c.metadata().containsKey("offered_qos_profiles")), "every channel CDR with its QoS: " + channels);
        Map<String, String> avoidTiming = channels.stream()
                .filter(c -> c.topic().equals("/rtaware/timing/avoid")).findFirst().orElseThrow().metadata();
        assertEquals("laser", avoidTiming.get("inputs"));

        Msg scanMsg = only(messages, "/scan");
        assertEquals(1_000, scanMsg.logTimeNs());
        LaserScan back = new LaserScan(8);
        Ros2Header header = new Ros2Header();
        new LaserScanCodec().decode(new CdrReader().wrap(scanMsg.data(), 0, scanMsg.data().length), header, back);
        assertEquals(3, back.count());
        assertEquals(2f, back.rangesM[1]);
        assertEquals(1_000, header.stampNs);
        assertEquals("base_link", header.frameId.toString());

        ObjectMapper json = new ObjectMapper();
        JsonNode state = json.readTree(jsonOf(only(messages, "/rtaware/state/laser")));
        assertEquals(12.5, state.get("serverTimeS").asDouble());
        assertTrue(state.get("rangesM") == null, "the state channel carries no arrays");
        JsonNode m = json.readTree(new String(jsonOf(only(messages, "/rtaware/data/motion.avoid")), StandardCharsets.UTF_8));
        assertEquals(0.25, m.get("vxMps").asDouble());
        assertEquals(true, m.get("active").asBoolean());
        JsonNode g = json.readTree(jsonOf(only(messages, "/rtaware/data/goals")));
        assertEquals(1, g.get("count").asInt());
        assertEquals(1, g.get("xM").size());
        assertEquals(7, g.get("id").get(0).asLong());

        List<Msg> timing = messages.stream().filter(x -> x.topic().equals("/rtaware/timing/avoid")).toList();
        assertEquals(2, timing.size());
        CdrReader r = new CdrReader().wrap(timing.get(0).data(), 0, timing.get(0).data().length);
        assertEquals(3_000, r.readInt64());
        assertEquals(3_500, r.readInt64());
        assertEquals(5_000, r.readInt64());
        assertEquals(0.0005, r.readFloat64());
        assertEquals(0.0015, r.readFloat64());
        StringBuilder outcome = new StringBuilder();
        r.readString(outcome);
        assertEquals("ok", outcome.toString());
        assertEquals(0, r.readInt64());
        assertEquals(1, r.readSequenceLength(8));
        assertEquals(1, r.readInt64());
        assertEquals(1, messages.stream().filter(x -> x.topic().equals("/rtaware/events")).count());
        assertEquals(6_000, only(messages, "/ground_truth").logTimeNs());

        McapSummary summary = reader.summary();
        assertEquals(11, summary.statistics().messageCount());

        // /rosout: rcl_interfaces/msg/Log, the run's own line, then the monitor's event in words.
        McapChannel rosout = channels.stream().filter(c -> c.topic().equals(RunRecorder.ROSOUT_TOPIC)).findFirst()
                .orElseThrow();
        assertEquals(Ros2Types.LOG.typeHash(), rosout.metadata().get("topic_type_hash"));
        List<Msg> lines = messages.stream().filter(x -> x.topic().equals(RunRecorder.ROSOUT_TOPIC)).toList();
        assertEquals(List.of(7_000L, 20_000L), lines.stream().map(Msg::logTimeNs).toList(),
                "at the line's and the event's time");
        assertEquals("7000 40 safety collision: the robot touched an obstacle (1 so far)", logLine(lines.get(0).data()));
        assertEquals("20000 30 avoid deadline miss: the release at 0.000 s did not end by its deadline at 0.000 s "
                + "(still running)", logLine(lines.get(1).data()));
    }

    /** An rcl_interfaces/msg/Log as "stamp level name msg", checking it names no file, function or line. */
    private static String logLine(byte[] data) {
        CdrReader in = new CdrReader().wrap(data, 0, data.length);
        long stampNs = in.readInt32() * 1_000_000_000L + in.readInt32();
        int level = in.readInt8();
        StringBuilder name = new StringBuilder();
        StringBuilder text = new StringBuilder();
        StringBuilder file = new StringBuilder();
        StringBuilder function = new StringBuilder();
        in.readString(name);
        in.readString(text);
        in.readString(file);
        in.readString(function);
        assertEquals("", file.toString() + function);
        assertEquals(0, in.readInt32(), "line");
        return stampNs + " " + level + " " + name + " " + text;
    }

    @Test
    void aFullRingDropsAndCountsInsteadOfBlocking() throws IOException {
        Path file = dir.resolve("drop.mcap");
        RecordingPlan plan = new RecordingPlan().slots(1, 1, 1);
        RunRecorder recorder = new RunRecorder(file, List.of("t"), List.of(List.of()), List.of(MOTION), plan);
        MotionRequest motion = new MotionRequest();
        long accepted = 0;
        for (int i = 0; i < 100_000; i++) {
            recorder.commit(0, i + 1, i, motion);
        }
        RecordingStats stats = recorder.finish();
        accepted = stats.messages();
        assertEquals(100_000, accepted + stats.dropped(), "every record is written or counted as dropped");
        assertTrue(stats.dropped() > 0, "a one-slot ring fed 100 000 commits in a loop drops some");
    }

    private static byte[] jsonOf(Msg m) {
        return StateJsonMessage.json(m.data(), 0, m.data().length);
    }

    private static Msg only(List<Msg> messages, String topic) {
        List<Msg> found = messages.stream().filter(m -> m.topic().equals(topic)).toList();
        assertEquals(1, found.size(), topic);
        return found.get(0);
    }
}
