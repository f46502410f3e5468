package io.rtaware.ros2msg;

import com.code_intelligence.jazzer.junit.FuzzTest;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.MetricsMessage;
import io.rtaware.ros2msg.value.PlanarPose;
import java.util.Arrays;

/**
 * Coverage-guided fuzzing of every CDR decoder with bytes from the network (issue 24): the first
 * byte picks the codec, the rest is the message. A decoder may refuse a message only with a
 * {@link CdrException} (what the ROS 2 data task counts as malformed); any other throwable is a
 * finding. Without {@code JAZZER_FUZZ=1} this runs the corpus in
 * {@code CdrDecodersFuzzTestInputs/} (seeded from the rosbags reference vectors, plus every
 * crash found since) as a regression test.
 */
class CdrDecodersFuzzTest {

    private final CdrReader reader = new CdrReader();
    private final Ros2Header header = new Ros2Header();
    private final LaserScan scan = new LaserScan(LaserScan.DEFAULT_CAPACITY);
    private final Odometry odometry = new Odometry();
    private final VelocityCommand twist = new VelocityCommand();
    private final PlannedPath path = new PlannedPath(PlannedPath.DEFAULT_CAPACITY);
    private final OccupancyGrid grid = new OccupancyGrid(64 * 1024);
    private final PlanarPose pose = new PlanarPose();
    private final DiagnosticArray diagnostics = new DiagnosticArray(16, 16);
    private final MetricsMessage metrics = new MetricsMessage(8);

    @FuzzTest(maxDuration = "20s")
    void decodingThrowsNothingButCdrException(byte[] input) {
        if (input.length == 0) {
            return;
        }
        byte[] message = Arrays.copyOfRange(input, 1, input.length);
        try {
            reader.wrap(message, 0, message.length);
            switch (Math.floorMod(input[0], 8)) {
                case 0 -> new LaserScanCodec().decode(reader, header, scan);
                case 1 -> new OdometryCodec("base_link").decode(reader, header, odometry);
                case 2 -> new TwistCodec().decode(reader, header, twist);
                case 3 -> new PathCodec().decode(reader, header, path);
                case 4 -> new OccupancyGridCodec().decode(reader, header, grid);
                case 5 -> new PoseStampedCodec().decode(reader, header, pose);
                case 6 -> new DiagnosticArrayCodec().decode(reader, header, diagnostics);
                default -> new MetricsMessageCodec().decode(reader, header, metrics);
            }
        } catch (CdrException refused) {
            // the documented way to refuse a malformed message
        }
    }
}
