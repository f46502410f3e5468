package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.testing.PythonPeers;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * The tests' independent ROS 2 node: {@code src/test/resources/ros2/ros2_peer.py} (eclipse-zenoh,
 * zenoh-ros2-sdk and rosbags) and the Python that runs it, named by {@code RTAWARE_PEER_PYTHON}
 * (.ci/run makes one; {@link PythonPeers#python()} finds it).
 */
public final class Ros2PythonPeer {

    private Ros2PythonPeer() {
    }

    /**
     * @param dir a folder of the test's
     * @return ros2_peer.py, copied into it
     * @throws IOException if it cannot be copied
     */
    public static Path script(Path dir) throws IOException {
        Path script = dir.resolve("ros2_peer.py");
        try (InputStream in = Objects.requireNonNull(Ros2PythonPeer.class.getResourceAsStream("/ros2/ros2_peer.py"))) {
            Files.copy(in, script);
        }
        return script;
    }

    /**
     * Issue 37: what a peer's {@code statistics} mode saw of {@code bench --tasks 2 --export}, live:
     * a window a second, and every task's four metrics and every key's two, ROS 2's units.
     *
     * @param seen the peer's JSON line
     */
    public static void assertStatisticsOfEveryTaskAndKey(JsonNode seen) {
        assertTrue(seen.path("windows").asInt() >= 3, "a window a second: " + seen);
        for (String task : List.of("t1", "t2")) {
            assertEquals("[\"release_lateness\",\"execution_time\",\"input_age\",\"deadline_misses\"]",
                    seen.path("sources").path(task).toString(), "every task's metrics: " + seen);
        }
        for (String key : List.of("t1.out", "t2.out")) {
            assertEquals("[\"message_period\",\"message_age\"]", seen.path("sources").path(key).toString(),
                    "every key's: " + seen);
        }
        assertEquals("ms", seen.path("first").path("t1.out message_period").path("unit").asText(), seen.toString());
        assertEquals("count", seen.path("first").path("t1 deadline_misses").path("unit").asText(), seen.toString());
    }
}
