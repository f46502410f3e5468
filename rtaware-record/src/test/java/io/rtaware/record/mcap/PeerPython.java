package io.rtaware.record.mcap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.PythonPeers;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Runs a script of {@code src/test/python} with the Python named by {@code RTAWARE_PEER_PYTHON}
 * (.ci/run sets it up with the packages of .ci/python-peers.txt); a test that calls it is
 * {@code @Requires(PythonPeers.class)}.
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
        String python = PythonPeers.python();
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
