package io.rtaware.record;

import io.rtaware.record.ring.SingleProducerSequence;
import io.rtaware.ros2msg.Ros2Codec;
import io.rtaware.ros2msg.TransformMessages;
import io.rtaware.ros2msg.value.PlanarPose;
import java.io.IOException;

/**
 * Ground-truth poses: filled by the one thread that samples them (the run's referee), written as
 * {@code geometry_msgs/msg/PoseStamped} in the {@code map} frame and, in a recording with
 * transforms, as the transform {@code map} to {@code ground_truth} on {@code /tf}.
 */
final class GroundTruthRing implements RecorderRing {

    /** The frame of the true pose, a child of {@code map} on {@code /tf} (when the recording has transforms). */
    static final String GROUND_TRUTH_FRAME = "ground_truth";

    private final int channel;
    @SuppressWarnings("rawtypes")
    private final Ros2Codec codec;
    private final long[] time;
    private final double[] x;
    private final double[] y;
    private final double[] yaw;
    private final PlanarPose pose = new PlanarPose();
    private final SingleProducerSequence sequence;
    private final long stampOffsetNs;
    private final int tfChannel;

    GroundTruthRing(int channel, int tfChannel, Ros2Codec<PlanarPose> codec, int slots, long stampOffsetNs) {
        this.channel = channel;
        this.tfChannel = tfChannel;
        this.stampOffsetNs = stampOffsetNs;
        this.codec = codec;
        time = new long[slots];
        x = new double[slots];
        y = new double[slots];
        yaw = new double[slots];
        sequence = new SingleProducerSequence(slots);
    }

    /** Producer (the sampling thread): copies a pose into a free slot; false (dropped) if none is free. */
    boolean offer(long timeNs, double xM, double yM, double yawRad) {
        long h = sequence.claim();
        if (h < 0) {
            return false;
        }
        int s = sequence.slot(h);
        time[s] = timeNs;
        x[s] = xM;
        y[s] = yM;
        yaw[s] = yawRad;
        sequence.publish(h);
        return true;
    }

    @Override
    @SuppressWarnings("unchecked")
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        long t = sequence.consumed();
        long h = sequence.published();
        for (long i = t; i < h; i++) {
            int s = sequence.slot(i);
            pose.set(x[s], y[s], yaw[s]);
            scratch.header.set(stampOffsetNs + time[s], "map");
            codec.encode(scratch.header, pose, scratch.cdr);
            sink.write(channel, i, time[s], time[s], scratch.cdr.buffer(), 0, scratch.cdr.size());
            if (tfChannel != 0) {
                TransformMessages.begin(scratch.cdr, 1);
                TransformMessages.transform(scratch.cdr, stampOffsetNs + time[s], "map", GROUND_TRUTH_FRAME, x[s], y[s],
                        yaw[s]);
                sink.write(tfChannel, i, time[s], time[s], scratch.cdr.buffer(), 0, scratch.cdr.size());
            }
            sequence.consumedUpTo(i + 1);
        }
        return (int) (h - t);
    }

    @Override
    public void discard() {
        sequence.discardAll();
    }
}
