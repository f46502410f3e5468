package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.NpmPeers;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Runs src/test/node/check_foxglove.mjs (Foxglove's {@code @mcap/core} indexed and streaming
 * readers with {@code @foxglove/rosmsg2-serialization} decoding every message) on a recording,
 * with node and the packages under {@code RTAWARE_NPM_PEERS} (.ci/run installs them); skips
 * without them, except under {@code CI=true}.
 */
public final class FoxgloveReadersCheck {

    private FoxgloveReadersCheck() {
    }

    /**
     * @param recording the MCAP file
     * @return what the checker printed (it passed)
     * @throws Exception if it cannot be run
     */
    public static String run(Path recording) throws Exception {
        String peers = NpmPeers.folder();
        Process p;
        try {
            ProcessBuilder pb = new ProcessBuilder("node", "src/test/node/check_foxglove.mjs", recording.toString())
                    .redirectErrorStream(true);
            pb.environment().put(NpmPeers.VARIABLE, peers);
            p = pb.start();
        } catch (IOException e) {
            throw new AssertionError("cannot run node: " + e.getMessage(), e);
        }
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "checker finished");
        assertEquals(0, p.exitValue(), output);
        return output;
    }
}
