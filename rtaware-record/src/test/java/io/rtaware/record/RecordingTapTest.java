package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Key;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapSchema;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2msg.RobotTopics;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A recording's tap (the live Foxglove server's feed) sees the channels and messages of the
 * file: the same ids, topics, types and schemas, the same CDR bytes at the same Unix-epoch log
 * times; and without a file the recorder feeds the tap alone.
 */
class RecordingTapTest {

    private static final Key<LaserScan> LASER = Key.of("laser", LaserScan.class, () -> new LaserScan(8));
    private static final Key<MotionRequest> MOTION = Key.of("motion.avoid", MotionRequest.class, MotionRequest::new);
    private static final long OFFSET_NS = 1_700_000_000_000_000_000L;

    @TempDir
    Path dir;

    /** A message as the tap or the file has it. */
    private record Msg(int channel, long logTimeNs, byte[] data) {
        @Override
        public boolean equals(Object o) {
            return o instanceof Msg m && m.channel == channel && m.logTimeNs == logTimeNs && Arrays.equals(m.data, data);
        }

        @Override
        public int hashCode() {
            return 31 * Long.hashCode(logTimeNs) + Arrays.hashCode(data);
        }

        @Override
        public String toString() {
            return "channel " + channel + " at " + logTimeNs + ": " + data.length + " bytes";
        }
    }

    /** Collects what the recorder hands its tap. */
    private static class CollectingTap implements RecordingTap {
        final List<TapChannel> channels = new CopyOnWriteArrayList<>();
        final List<Msg> messages = new CopyOnWriteArrayList<>();

        @Override
        public void channel(TapChannel channel) {
            channels.add(channel);
        }

        @Override
        public void message(int channelId, long logTimeNs, byte[] data, int offset, int length) {
            assertTrue(channels.stream().anyMatch(c -> c.id() == channelId), "a message after its channel: " + channelId);
            messages.add(new Msg(channelId, logTimeNs, Arrays.copyOfRange(data, offset, offset + length)));
        }

        String topic(int channelId) {
            return channels.stream().filter(c -> c.id() == channelId).findFirst().orElseThrow().topic();
        }
    }

    private static RecordingPlan plan(CollectingTap tap) {
        return new RecordingPlan().topic("laser", "/scan", "laser").logTimeOffsetNs(OFFSET_NS).withGroundTruth()
                .staticTransform("base_link", "laser", 0, 0, 0).tap(tap);
    }

    private static void feed(RunRecorder recorder) {
        LaserScan scan = new LaserScan(8);
        scan.minAngleRad = -1;
        scan.maxAngleRad = 1;
        scan.maxRangeM = 5;
        scan.setCount(3);
        scan.rangesM[0] = 1;
        scan.rangesM[1] = 2;
        scan.rangesM[2] = 3;
        recorder.commit(0, 1, 1_000, scan);
        MotionRequest motion = new MotionRequest();
        motion.request(0.25, -0.5);
        recorder.commit(1, 1, 2_000, motion);
        recorder.cycle(0, RunRecorder.OK, 3_000, 3_500, 5_000, 0, new long[] {1});
        recorder.cycle(0, RunRecorder.MISS, 10_000, 10_000, 30_000, 0, new long[] {1});
        recorder.event(RunRecorder.DEADLINE_MISS, 0, 20_000, 10_000, 20_000, true, null, null);
        recorder.groundTruth(6_000, 1, 2, 0.5);
    }

    @Test
    void theTapSeesTheFilesChannelsAndMessagesByteForByte() throws IOException {
        Path file = dir.resolve("run.mcap");
        CollectingTap tap = new CollectingTap();
        RunRecorder recorder = new RunRecorder(file, List.of("avoid"), List.of(List.of("laser")),
                List.of(LASER, MOTION), plan(tap));
        feed(recorder);
        RecordingStats stats = recorder.finish();
        assertNull(stats.error());

        Map<Integer, McapSchema> schemas = new HashMap<>();
        List<McapChannel> fileChannels = new ArrayList<>();
        List<Msg> fileMessages = new ArrayList<>();
        McapReader.open(file).read(new McapVisitor() {
            @Override
            public void schema(McapSchema schema) {
                schemas.put(schema.id(), schema);
            }

            @Override
            public void channel(McapChannel channel) {
                fileChannels.add(channel);
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                                int offset, int length) {
                fileMessages.add(new Msg(channel.id(), logTimeNs, Arrays.copyOfRange(data, offset, offset + length)));
            }
        });
        assertEquals(fileChannels.size(), tap.channels.size(), "as many channels: " + tap.channels);
        for (McapChannel c : fileChannels) {
            TapChannel t = tap.channels.stream().filter(x -> x.id() == c.id()).findFirst().orElseThrow(
                    () -> new AssertionError("the tap lacks channel " + c.id() + " " + c.topic()));
            McapSchema schema = schemas.get(c.schemaId());
            assertEquals(c.topic(), t.topic(), "topic of channel " + c.id());
            assertEquals(schema.name(), t.schemaName(), "type of " + c.topic());
            assertEquals(schema.data(), t.schema(), "ros2msg schema of " + c.topic());
            assertEquals(schema.encoding(), TapChannel.SCHEMA_ENCODING, "schema encoding of " + c.topic());
            assertEquals(c.messageEncoding(), TapChannel.MESSAGE_ENCODING, "message encoding of " + c.topic());
            assertEquals(c.topic().equals(RobotTopics.TF_STATIC), t.latched(), "latched: " + c.topic());
        }
        Comparator<Msg> order = Comparator.comparingLong(Msg::logTimeNs).thenComparingInt(Msg::channel);
        List<Msg> fromTap = new ArrayList<>(tap.messages);
        fromTap.sort(order);
        fileMessages.sort(order);
        assertEquals(fileMessages, fromTap, "the same messages, bytes and Unix-epoch log times");
        assertTrue(fromTap.stream().allMatch(m -> m.logTimeNs() >= OFFSET_NS), "log times are world time plus the offset");
    }

    @Test
    void withoutAFileTheRecorderFeedsItsTapAlone() throws IOException {
        CollectingTap tap = new CollectingTap();
        RunRecorder recorder = new RunRecorder((Path) null, List.of("avoid"), List.of(List.of("laser")),
                List.of(LASER, MOTION), plan(tap));
        feed(recorder);
        RecordingStats stats = recorder.finish();
        assertNull(stats.error());
        assertNull(stats.file(), "no file");
        assertNull(recorder.file());
        assertEquals(0, stats.dropped());
        try (var files = Files.list(dir)) {
            assertFalse(files.findAny().isPresent(), "nothing written to disk");
        }
        List<Integer> ids = tap.channels.stream().map(TapChannel::id).toList();
        List<Integer> expected = new ArrayList<>();
        for (int i = 1; i <= ids.size(); i++) {
            expected.add(i);
        }
        assertEquals(expected, ids, "channels numbered from 1 as a file would number them");
        TapChannel scan = tap.channels.stream().filter(c -> c.topic().equals("/scan")).findFirst().orElseThrow();
        assertEquals("sensor_msgs/msg/LaserScan", scan.schemaName());
        assertTrue(scan.schema().contains("float32[] ranges"), "the ros2msg definition: " + scan.schema());
        assertTrue(tap.channels.stream().anyMatch(c -> c.topic().equals("/rtaware/timing/avoid")
                && c.schemaName().equals("rtaware_msgs/msg/TaskCycle")), "the timing channel: " + tap.channels);
        // scan + its state, motion, 2 cycles, 1 event + its /rosout line, 1 pose + its /tf, /tf_static
        assertEquals(10, tap.messages.size(), "every message: " + tap.messages);
        long scans = tap.messages.stream().filter(m -> m.channel() == scan.id()).count();
        assertEquals(1, scans, "one scan");
        assertEquals(OFFSET_NS + 1_000, tap.messages.stream().filter(m -> m.channel() == scan.id()).findFirst()
                .orElseThrow().logTimeNs(), "the scan's log time: its commit plus the offset");
    }

    /**
     * {@code /tf} comes from two rings (odometry's transforms and the ground truth's), which the
     * writer drains one after the other: odometry's ring first in each pass. The tap holds the
     * writer inside its first {@code /odom} message until the test has handed both rings a run of
     * samples, so the writer then finds odometry's transforms up to 290 ms before the ground
     * truth's from 210 ms on: handed on in drain order, {@code /tf} would go back in time.
     */
    @Test
    void theTapGetsEveryChannelInLogTimeOrderWhenTheRingsAreDrainedOutOfOrder() throws Exception {
        CountDownLatch inFirstOdom = new CountDownLatch(1);
        CountDownLatch handedOver = new CountDownLatch(1);
        CollectingTap tap = new CollectingTap() {
            private boolean first = true;

            @Override
            public void message(int channelId, long logTimeNs, byte[] data, int offset, int length) {
                super.message(channelId, logTimeNs, data, offset, length);
                if (first && topic(channelId).equals(RobotTopics.ODOM)) {
                    first = false;
                    inFirstOdom.countDown();
                    await(handedOver);
                }
            }
        };
        long msNs = 1_000_000L;
        RecordingPlan plan = RobotRecordingPlan.create().withGroundTruth().logTimeOffsetNs(OFFSET_NS).reorderWindowNs(100 * msNs).tap(tap);
        RunRecorder recorder = new RunRecorder((Path) null, List.of(), List.of(), List.of(RobotKeys.ODOMETRY), plan);
        Odometry odometry = new Odometry();
        recorder.commit(0, 1, 0, odometry);
        recorder.commit(0, 2, 200 * msNs, odometry); // with a reorder window, what releases the first
        assertTrue(inFirstOdom.await(30, TimeUnit.SECONDS), "the writer reached the first /odom");
        for (int i = 0; i < 9; i++) {
            long t = (210 + 10 * i) * msNs;
            recorder.groundTruth(t, 1, 2, 0.5);
            odometry.xM = i;
            recorder.commit(0, 3 + i, t, odometry);
        }
        handedOver.countDown();
        RecordingStats stats = recorder.finish();
        assertNull(stats.error());

        Map<Integer, Long> last = new HashMap<>();
        for (Msg m : tap.messages) {
            long before = last.getOrDefault(m.channel(), Long.MIN_VALUE);
            assertTrue(m.logTimeNs() >= before, tap.topic(m.channel()) + " went back in time from "
                    + (before - OFFSET_NS) + " to " + (m.logTimeNs() - OFFSET_NS) + " ns");
            last.put(m.channel(), m.logTimeNs());
        }
        int tf = tap.channels.stream().filter(c -> c.topic().equals(RobotTopics.TF)).findFirst().orElseThrow().id();
        assertEquals(11 + 9, tap.messages.stream().filter(m -> m.channel() == tf).count(),
                "every odometry and ground-truth transform reached the tap");
    }

    private static void await(CountDownLatch latch) {
        try {
            assertTrue(latch.await(30, TimeUnit.SECONDS), "the test handed the records over");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
    }

    @Test
    void aRecordingWithNeitherFileNorTapIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new RunRecorder((Path) null,
                List.of(), List.of(), List.of(LASER), new RecordingPlan()));
        assertTrue(e.getMessage().contains("a file, a tap or both"), e.getMessage());
    }
}
