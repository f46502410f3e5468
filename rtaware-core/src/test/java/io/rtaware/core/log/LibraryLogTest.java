package io.rtaware.core.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;

/**
 * A library's log record is one plain line on the stream the program chose, or nothing below the
 * level; never java.util.logging's two-line record on the root console handler.
 */
class LibraryLogTest {

    /** Records that reach the root logger's handlers, where the JDK's console handler prints two lines each. */
    private static final class RootRecords extends Handler implements AutoCloseable {
        final List<String> messages = new ArrayList<>();

        RootRecords() {
            Logger.getLogger("").addHandler(this);
        }

        @Override
        public void publish(LogRecord record) {
            if (record.getLoggerName() != null && record.getLoggerName().startsWith(LibraryLog.NAMESPACE)) {
                messages.add(record.getMessage());
            }
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
            Logger.getLogger("").removeHandler(this);
        }
    }

    @Test
    void warningsAreOneLineAndInformationIsDropped() {
        System.Logger library = System.getLogger("io.rtaware.sim.server.PlayerSimServer");
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (RootRecords root = new RootRecords()) {
            try (LibraryLog log = LibraryLog.oneLineEach(new PrintStream(bytes, true, StandardCharsets.UTF_8),
                    System.Logger.Level.WARNING)) {
                library.log(System.Logger.Level.INFO, "rtaware-sim: serving Player on 127.0.0.1:6665");
                library.log(System.Logger.Level.WARNING, "rtaware-sim: disconnecting client a: too slow\nsecond line");
            }
            assertEquals("rtaware-sim: disconnecting client a: too slow\n",
                    bytes.toString(StandardCharsets.UTF_8).replace("\r\n", "\n"), "one line, the message's first");
            assertEquals(List.of(), root.messages, "nothing reaches the root console handler");

            library.log(System.Logger.Level.INFO, "after close");
            assertTrue(root.messages.contains("after close"), "closing restores the logger as it was");
        }
    }
}
