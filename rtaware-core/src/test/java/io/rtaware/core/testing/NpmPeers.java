package io.rtaware.core.testing;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Foxglove's own readers and WebSocket client of {@code .ci/npm-peers.json}: a folder whose
 * {@code node_modules} holds them, named by {@code RTAWARE_NPM_PEERS} ({@code .ci/run} installs
 * them under {@code ~/.cache/rtaware/npm-peers}), run with {@code node}.
 */
public final class NpmPeers implements Requirement {

    /** The environment variable that names the folder. */
    public static final String VARIABLE = "RTAWARE_NPM_PEERS";

    /**
     * @return the folder, as {@code RTAWARE_NPM_PEERS} names it; skips the test without it, and fails it
     *     under {@code CI=true} ({@link RequiresExtension#require})
     */
    public static String folder() {
        RequiresExtension.require(new NpmPeers());
        return System.getenv(VARIABLE);
    }

    @Override
    public String name() {
        return "the npm peers (" + VARIABLE + ")";
    }

    @Override
    public String missingReason() {
        String folder = System.getenv(VARIABLE);
        if (folder == null || folder.isBlank()) {
            return VARIABLE + " is unset (.ci/run sets it to a folder with the packages of .ci/npm-peers.json)";
        }
        return Files.isDirectory(Path.of(folder, "node_modules")) ? null
                : VARIABLE + "=" + folder + " has no node_modules folder";
    }
}
