package io.rtaware.robotrun;

import java.util.List;
import java.util.Map;

/**
 * The {@code ros2} section of a run's {@code report.json} when the robot was a ROS 2 robot
 * ({@code run --ros2}): what the ROS 2 data task received, dropped and sent.
 *
 * @param robot where the robot was, in words
 * @param transport how the robot was reached: {@code rmw_zenoh}, or {@code dds} ({@code --dds},
 *     through the ROS 2 DDS bridge)
 * @param rosDistro the ROS 2 distribution whose rmw_zenoh conventions were followed
 *     ({@code --ros-distro}: {@code humble}, {@code jazzy}, {@code kilted} or {@code rolling})
 * @param scans scans committed
 * @param odometry odometry samples committed
 * @param commands Twist messages published
 * @param rejectedSamples decoded samples dropped because their values cannot be true, by fully
 *     qualified topic name (e.g. {@code /robot1/scan})
 * @param malformed samples that could not be decoded
 * @param oversized samples larger than the largest accepted message
 * @param overflowed samples dropped because the data task fell behind
 * @param otherPublisherSamples samples dropped because another publisher than the first one
 *     heard on their topic sent them
 * @param clockEpochs new epochs of a topic's clock that were followed (a restarted or jumped
 *     robot clock)
 * @param notices one line per event reported once: another publisher on an input topic (also
 *     on the built-in simulator's {@code cmd_vel}), a new clock epoch
 * @param lastProblem the last reason a sample was dropped, or null
 * @param fault why the robot was halted (a topic sent only impossible samples), or null
 * @param scanLatencyMs a scan's source timestamp to its commit in the store, {@code p50} and {@code p99};
 *     null when no scan carried a source timestamp (over DDS from a robot stamping simulated time)
 * @param scanLatencyFrom what the source timestamp was: rmw_zenoh's attachment, or over DDS the
 *     header stamp (a driver's acquisition time); null with {@code scanLatencyMs}
 * @param cpuUsPerSample the data task's CPU time per received sample, microseconds
 * @param droppedBeams scan readings that said nothing (NaN, beyond the maximum range), dropped
 *     from scans that were kept
 */
public record Ros2Section(String robot, String transport, String rosDistro, long scans, long odometry, long commands, Map<String, Long> rejectedSamples,
                          long malformed, long oversized, long overflowed, long otherPublisherSamples,
                          long clockEpochs, List<String> notices, String lastProblem, String fault,
                          Map<String, Double> scanLatencyMs, String scanLatencyFrom, double cpuUsPerSample,
                          long droppedBeams) {
}
