package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.PythonPeers;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Runs src/test/python/check_ros2_profile.py (the Python {@code mcap} reader and
 * {@code rosbags}' AnyReader) on a recording, with the Python of {@code RTAWARE_PEER_PYTHON};
 * skips without one, except under {@code CI=true}.
 */
public final class Ros2ProfileCheck {

    private Ros2ProfileCheck() {
    }

    /**
     * @param recording the MCAP file
     * @return what the checker printed (it passed)
     * @throws Exception if it cannot be run
     */
    public static String run(Path recording) throws Exception {
        String python = PythonPeers.python();
        Process p = new ProcessBuilder(python, "src/test/python/check_ros2_profile.py", recording.toString())
                .redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "checker finished");
        assertEquals(0, p.exitValue(), output);
        return output;
    }
}
