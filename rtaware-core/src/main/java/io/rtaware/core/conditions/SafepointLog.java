package io.rtaware.core.conditions;

import java.io.BufferedReader;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.management.JMException;
import javax.management.MBeanServer;
import javax.management.ObjectName;

/**
 * The JVM's own safepoint log, switched on for a span of time and read when it ends: HotSpot's
 * unified logging writes one line per safepoint ({@code safepoint=info}) from the VM thread, as
 * the safepoint ends, to a file output this class adds at the start and removes at the end
 * through the {@code VM.log} diagnostic command (what {@code jcmd PID VM.log} does). Nothing runs
 * beside the tasks meanwhile: no thread, no buffer flushed every second, no event parsing, which
 * is what a JFR recording cost 10 000 pooled tasks at 10 ms (issue 36).
 *
 * <p>A line says the operation and, in nanoseconds, the time the threads took to reach the
 * safepoint, the operation itself and the total; JDK 17 writes {@code Reaching safepoint: N ns,
 * Cleanup: N ns, At safepoint: N ns, Total: N ns}, JDK 21 and later {@code Reaching safepoint:
 * N ns, At safepoint: N ns, Leaving safepoint: N ns, Total: N ns, Threads: ...}: the fields are
 * read by name. Where the command is missing (not HotSpot) or refused, {@link #start} says why
 * and nothing is measured. Not thread-safe: one owner starts and stops it.
 */
final class SafepointLog {

    /** A safepoint: its operation and how long it held the threads, ns. */
    record Safepoint(String operation, long reachingNs, long atSafepointNs, long totalNs) {

        /**
         * @param operation the VM operation that took the safepoint, e.g. {@code ZMarkStart}
         * @param reachingNs the time from the request until the last thread stopped
         * @param atSafepointNs the operation's own time, all threads stopped
         * @param totalNs from the request until the threads were let go
         */
        Safepoint {
        }

        /**
         * @return whether the operation is a collector's pause (by the names HotSpot's
         *     collectors give their safepoint operations: Serial, Parallel, G1, ZGC, Shenandoah)
         */
        boolean collectorPause() {
            for (String prefix : COLLECTOR_OPERATIONS) {
                if (operation.startsWith(prefix)) {
                    return true;
                }
            }
            return false;
        }
    }

    /** Operation name prefixes of HotSpot's collectors' safepoints (vmOperation.hpp, JDK 17 to 25). */
    private static final List<String> COLLECTOR_OPERATIONS = List.of("ParallelGC", "G1", "ZMark", "ZRelocate",
            "Shenandoah", "GenCollect", "SerialCollect", "SerialGC", "CollectForMetadataAllocation",
            "CollectForCodeCacheAllocation");

    private static final Pattern LINE = Pattern.compile("Safepoint \"([^\"]+)\".*?Reaching safepoint: (\\d+) ns.*?"
            + "At safepoint: (\\d+) ns.*?Total: (\\d+) ns");
    private static final String DIAGNOSTIC_COMMAND = "com.sun.management:type=DiagnosticCommand";

    private final Path file;
    private final MBeanServer server;
    private final ObjectName command;

    private SafepointLog(Path file, MBeanServer server, ObjectName command) {
        this.file = file;
        this.server = server;
        this.command = command;
    }

    /**
     * Adds a log output for the safepoints to {@code file} (a new, empty file the caller owns).
     *
     * @param file where the JVM writes the lines
     * @return the log
     * @throws IOException why it cannot be switched on (no diagnostic command, or it refused)
     */
    static SafepointLog start(Path file) throws IOException {
        String path = file.toAbsolutePath().toString();
        if (!path.matches("[^\\s\",=]+")) {
            throw new IOException("its file's path holds a space, comma, quote or '=', which VM.log cannot take: " + path);
        }
        MBeanServer server = ManagementFactory.getPlatformMBeanServer();
        try {
            ObjectName command = new ObjectName(DIAGNOSTIC_COMMAND);
            if (!server.isRegistered(command)) {
                throw new IOException("this JVM has no diagnostic commands (" + DIAGNOSTIC_COMMAND + ")");
            }
            SafepointLog log = new SafepointLog(file, server, command);
            log.vmLog("what=safepoint=info", "decorators=uptimenanos", "output_options=filecount=0");
            return log;
        } catch (JMException | RuntimeException e) {
            throw new IOException("VM.log refused: " + e.getMessage(), e);
        }
    }

    /**
     * Removes the output (the JVM closes the file) and reads what it wrote.
     *
     * @return the safepoints, in the order they ended
     * @throws IOException if the output cannot be removed or the file read
     */
    List<Safepoint> stop() throws IOException {
        try {
            vmLog("what=all=off");
        } catch (JMException | RuntimeException e) {
            throw new IOException("VM.log could not remove its output: " + e.getMessage(), e);
        }
        List<Safepoint> safepoints = new ArrayList<>();
        try (BufferedReader lines = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            for (String line = lines.readLine(); line != null; line = lines.readLine()) {
                Safepoint safepoint = parse(line);
                if (safepoint != null) {
                    safepoints.add(safepoint);
                }
            }
        }
        return safepoints;
    }

    /**
     * @param line a line of the safepoint log
     * @return its safepoint, or null if the line is not one
     */
    static Safepoint parse(String line) {
        Matcher m = LINE.matcher(line);
        if (!m.find()) {
            return null;
        }
        return new Safepoint(m.group(1), Long.parseLong(m.group(2)), Long.parseLong(m.group(3)),
                Long.parseLong(m.group(4)));
    }

    private void vmLog(String... arguments) throws JMException {
        String[] withOutput = new String[arguments.length + 1];
        withOutput[0] = "output=file=" + file.toAbsolutePath();
        System.arraycopy(arguments, 0, withOutput, 1, arguments.length);
        server.invoke(command, "vmLog", new Object[] {withOutput}, new String[] {String[].class.getName()});
    }
}
