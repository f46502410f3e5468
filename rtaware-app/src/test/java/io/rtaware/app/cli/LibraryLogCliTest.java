package io.rtaware.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.RtawareCli;
import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;

/**
 * Issue 34: {@code sim} printed java.util.logging's two-line INFO record repeating its own stdout
 * line ("serving Player on ..."). The command routes the libraries' log once: nothing reaches the
 * root console handler.
 */
class LibraryLogCliTest {

    @Test
    void simsLogNeverReachesTheRootConsoleHandler() throws Exception {
        List<String> atRoot = new CopyOnWriteArrayList<>();
        Handler root = new Handler() {
            @Override
            public void publish(LogRecord record) {
                if (record.getLoggerName() != null && record.getLoggerName().startsWith("io.rtaware")) {
                    atRoot.add(record.getLevel() + " " + record.getMessage());
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        CountDownLatch started = new CountDownLatch(1);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        OutputStream signalling = new OutputStream() {
            @Override
            public synchronized void write(int b) {
                out.write(b);
                if (b == '\n') {
                    started.countDown();
                }
            }
        };
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream savedOut = System.out;
        PrintStream savedErr = System.err;
        AtomicInteger status = new AtomicInteger(-1);
        Logger.getLogger("").addHandler(root);
        try {
            System.setOut(new PrintStream(signalling, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            Thread sim = new Thread(() -> status.set(RtawareCli.execute("sim", "--port", "0")), "sim-under-test");
            sim.start();
            assertTrue(started.await(60, TimeUnit.SECONDS), "the simulator printed its start line");
            sim.interrupt();
            sim.join();
        } finally {
            System.setOut(savedOut);
            System.setErr(savedErr);
            Logger.getLogger("").removeHandler(root);
        }
        assertEquals(0, status.get(), err.toString(StandardCharsets.UTF_8));
        assertTrue(out.toString(StandardCharsets.UTF_8).contains("127.0.0.1"), out.toString(StandardCharsets.UTF_8));
        assertEquals(List.of(), atRoot, "records that java.util.logging's console handler would print in two lines");
        // (Jazzer's agent, once a fuzz test has run in this JVM, logs the classes it instruments: not ours)
        assertEquals(List.of(), err.toString(StandardCharsets.UTF_8).lines()
                .filter(l -> !l.startsWith("INFO: Instrumented ")).toList(), "the start line is not repeated on stderr");
    }
}
