package io.rtaware.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Under {@code LC_ALL=C} the JVM reads file names as ASCII, so a scenario path with a non-ASCII
 * letter cannot even be named: one line and exit status 2, not an InvalidPathException. Runs the
 * command in a child JVM with that locale; the path's UTF-8 bytes are made by the shell, so the
 * test does not depend on the locale of the JVM running it.
 */
class NonAsciiPathTest {

    @TempDir
    Path dir;

    @Test
    void aNonAsciiScenarioPathUnderTheCLocaleIsOneLine() throws IOException, InterruptedException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String script = "exec \"$0\" -cp \"$1\" io.rtaware.app.RtawareCli run --scenario \"$2/caf$(printf '\\303\\251').yaml\""
                + " --out \"$2/out\" --quiet";
        ProcessBuilder pb = new ProcessBuilder(List.of("sh", "-c", script, java, System.getProperty("java.class.path"),
                dir.toString()));
        pb.environment().keySet().removeIf(k -> k.startsWith("LC_") || k.equals("LANG") || k.equals("JAVA_TOOL_OPTIONS"));
        pb.environment().put("LC_ALL", "C");
        pb.redirectErrorStream(false);
        Process p = pb.start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the child ends");
        assertEquals(2, p.exitValue(), "exit status; stderr:\n" + err + "\nstdout:\n" + out);
        assertEquals(1, err.lines().count(), "one line: " + err);
        assertFalse(err.contains("Exception"), "no exception: " + err);
        assertTrue(err.contains("scenario '") && err.contains("LC_ALL=C.UTF-8"), "names the option and the cause: " + err);
    }
}
