package io.rtaware.core.testing;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The independent Python readers and ROS 2 nodes of {@code .ci/python-peers.txt}: a Python with
 * them, named by {@code RTAWARE_PEER_PYTHON} ({@code .ci/run} makes one under
 * {@code ~/.cache/rtaware/peer-venv}).
 */
public final class PythonPeers implements Requirement {

    /** The environment variable that names the peers' Python. */
    public static final String VARIABLE = "RTAWARE_PEER_PYTHON";

    /**
     * @return the peers' Python, as {@code RTAWARE_PEER_PYTHON} names it; skips the test without it, and
     *     fails it under {@code CI=true} ({@link RequiresExtension#require})
     */
    public static String python() {
        RequiresExtension.require(new PythonPeers());
        return System.getenv(VARIABLE);
    }

    @Override
    public String name() {
        return "the Python peers (" + VARIABLE + ")";
    }

    @Override
    public String missingReason() {
        String python = System.getenv(VARIABLE);
        if (python == null || python.isBlank()) {
            return VARIABLE + " is unset (.ci/run sets it to a Python with the packages of .ci/python-peers.txt)";
        }
        return Files.isExecutable(Path.of(python)) ? null : VARIABLE + "=" + python + " is not an executable";
    }
}
