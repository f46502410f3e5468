package io.rtaware.record;

import io.rtaware.record.ring.SingleProducerRing;
import io.rtaware.record.ring.SlotReader;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.Ros2Codec;
import io.rtaware.ros2msg.TransformMessages;
import io.rtaware.ros2msg.value.PlanarPose;
import java.io.IOException;

/**
 * Ground-truth poses: filled by the one thread that samples them (the run's referee), written as
 * {@code geometry_msgs/msg/PoseStamped} in the {@code world} frame and, in a recording with
 * transforms, as the transform {@code world} to {@code ground_truth} on {@code /tf}.
 */
final class GroundTruthRing implements RecorderRing {

    /** One sampled pose. */
    private static final class Sample {
        long timeNs;
        double xM;
        double yM;
        double yawRad;
    }

    private final int channel;
    @SuppressWarnings("rawtypes")
    private final Ros2Codec codec;
    private final PlanarPose pose = new PlanarPose();
    private final SingleProducerRing<Sample> ring;
    private final SlotReader<Sample, MessageSink, WriterScratch> writer = this::write;
    private final long stampOffsetNs;
    private final int tfChannel;

    GroundTruthRing(int channel, int tfChannel, Ros2Codec<PlanarPose> codec, int slots, long stampOffsetNs) {
        this.channel = channel;
        this.tfChannel = tfChannel;
        this.stampOffsetNs = stampOffsetNs;
        this.codec = codec;
        ring = new SingleProducerRing<>(slots, i -> new Sample());
    }

    /** Producer (the sampling thread): copies a pose into a free slot; false (dropped) if none is free. */
    boolean offer(long timeNs, double xM, double yM, double yawRad) {
        long position = ring.claim();
        if (position < 0) {
            return false;
        }
        Sample s = ring.slot(position);
        s.timeNs = timeNs;
        s.xM = xM;
        s.yM = yM;
        s.yawRad = yawRad;
        ring.publish(position);
        return true;
    }

    @Override
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        return ring.drain(writer, sink, scratch);
    }

    @SuppressWarnings("unchecked")
    private void write(Sample s, long position, MessageSink sink, WriterScratch scratch) throws IOException {
        pose.set(s.xM, s.yM, s.yawRad);
        scratch.header.set(stampOffsetNs + s.timeNs, RobotTopics.WORLD_FRAME);
        codec.encode(scratch.header, pose, scratch.cdr);
        sink.write(channel, position, s.timeNs, s.timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        if (tfChannel != 0) {
            TransformMessages.begin(scratch.cdr, 1);
            TransformMessages.transform(scratch.cdr, stampOffsetNs + s.timeNs, RobotTopics.WORLD_FRAME, RobotTopics.GROUND_TRUTH_FRAME, s.xM, s.yM,
                    s.yawRad);
            sink.write(tfChannel, position, s.timeNs, s.timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        }
    }

    @Override
    public void discard() {
        ring.discard(s -> { });
    }
}
