package io.rtaware.record.mcap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Runs a script of {@code src/test/python} with the Python named by {@code RTAWARE_PEER_PYTHON}
 * (.ci/run sets it up with the packages of .ci/python-peers.txt); skips without one, except
 * under {@code CI=true}, where its absence fails.
 */
final class PeerPython {

    private PeerPython() {
    }

    /**
     * @param script the script's file name in src/test/python
     * @param args its arguments
     * @return what it printed (stdout and stderr)
     * @throws Exception if it cannot be run; fails the test if it exits non-zero
     */
    static String run(String script, String... args) throws Exception {
        String python = System.getenv("RTAWARE_PEER_PYTHON");
        if (python == null || python.isBlank()) {
            if ("true".equals(System.getenv("CI"))) {
                throw new AssertionError("CI=true but RTAWARE_PEER_PYTHON is unset: .ci/run must set up the Python peers");
            }
            assumeTrue(false, "RTAWARE_PEER_PYTHON unset: skipping the check against an independent implementation");
        }
        List<String> command = new ArrayList<>(List.of(python, "src/test/python/" + script));
        command.addAll(List.of(args));
        Process p;
        try {
            p = new ProcessBuilder(command).redirectErrorStream(true).start();
        } catch (IOException e) {
            throw new AssertionError("cannot run " + python + ": " + e.getMessage(), e);
        }
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), script + " finished");
        assertEquals(0, p.exitValue(), script + " failed:\n" + output);
        return output;
    }
}
