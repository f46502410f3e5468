package io.rtaware.robotrun;

import io.rtaware.player.task.DeviceSamples;
import java.util.Map;

/**
 * The {@code player} section of a run's {@code report.json}: the robot server's connection and,
 * per device, the samples received and those rejected because they could not be true.
 *
 * @param server {@code host:port}
 * @param serverVersion the version the server announced
 * @param connects successful connections of the data task
 * @param connectionLosses connections it lost or failed to make
 * @param protocolErrors malformed messages
 * @param devices per device ({@code position2d:0}, {@code laser:0}, and {@code simulation:0} for
 *     the referee's ground truth): {@code samples}, {@code rejected_samples}, {@code last_rejection}
 * @param fault the line that halted the robot because a device sent only impossible data, or null
 */
public record PlayerSection(String server, String serverVersion, long connects, long connectionLosses,
                            long protocolErrors, Map<String, DeviceSamples> devices, String fault) {
}
