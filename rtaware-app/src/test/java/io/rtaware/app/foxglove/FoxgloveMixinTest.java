package io.rtaware.app.foxglove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.foxglove.FoxgloveServer;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** What {@code --foxglove} prints: the truth about where it listens, and a warning when exposed. */
class FoxgloveMixinTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private FoxgloveServer start(String value) {
        FoxgloveMixin mixin = new FoxgloveMixin();
        mixin.address = value;
        return mixin.start("run", new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    @Test
    void aBarePortPrintsTheLoopbackUrlAndNoWarning() {
        try (FoxgloveServer server = start("0")) {
            assertEquals("foxglove: " + server.url() + " (in Foxglove: Open connection, Foxglove WebSocket)\n",
                    out.toString(StandardCharsets.UTF_8));
            assertEquals("", err.toString(StandardCharsets.UTF_8));
        }
    }

    @Test
    void everyAddressIsSaidAndWarnedOf() {
        try (FoxgloveServer server = start("0:0")) {
            String line = out.toString(StandardCharsets.UTF_8);
            assertTrue(line.contains("listening on " + server.listening() + ", reachable from other machines"), line);
            String warning = err.toString(StandardCharsets.UTF_8);
            assertEquals(1, warning.lines().count(), warning);
            assertTrue(warning.startsWith("warning: --foxglove listens on " + server.listening() + ": anyone"), warning);
        }
    }
}
