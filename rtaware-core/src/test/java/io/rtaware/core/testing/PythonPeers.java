package io.rtaware.core.testing;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The independent Python readers and ROS 2 nodes of {@code .ci/python-peers.txt}: a Python with
 * them, named by {@code RTAWARE_PEER_PYTHON} ({@code .ci/run} makes one under
 * {@code ~/.cache/rtaware/peer-venv}).
 */
public final class PythonPeers extends VariableRequirement {

    /** The environment variable that names the peers' Python. */
    public static final String VARIABLE = "RTAWARE_PEER_PYTHON";

    /** As {@link Requires} makes it. */
    public PythonPeers() {
        super(VARIABLE, "the Python peers", "a Python with the packages of .ci/python-peers.txt");
    }

    /**
     * @return the peers' Python, as {@code RTAWARE_PEER_PYTHON} names it; skips the test without it, and
     *     fails it under {@code CI=true} ({@link RequiresExtension#require})
     */
    public static String python() {
        return new PythonPeers().required();
    }

    @Override
    String unusable(String value) {
        return Files.isExecutable(Path.of(value)) ? null : "is not an executable";
    }
}
