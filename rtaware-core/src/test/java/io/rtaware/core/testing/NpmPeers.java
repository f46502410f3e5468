package io.rtaware.core.testing;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Foxglove's own readers and WebSocket client of {@code .ci/npm-peers.json}: a folder whose
 * {@code node_modules} holds them, named by {@code RTAWARE_NPM_PEERS} ({@code .ci/run} installs
 * them under {@code ~/.cache/rtaware/npm-peers}), run with {@code node}.
 */
public final class NpmPeers extends VariableRequirement {

    /** The environment variable that names the folder. */
    public static final String VARIABLE = "RTAWARE_NPM_PEERS";

    /** As {@link Requires} makes it. */
    public NpmPeers() {
        super(VARIABLE, "the npm peers", "a folder with the packages of .ci/npm-peers.json");
    }

    /**
     * @return the folder, as {@code RTAWARE_NPM_PEERS} names it; skips the test without it, and fails it
     *     under {@code CI=true} ({@link RequiresExtension#require})
     */
    public static String folder() {
        return new NpmPeers().required();
    }

    @Override
    String unusable(String value) {
        return Files.isDirectory(Path.of(value, "node_modules")) ? null : "has no node_modules folder";
    }
}
