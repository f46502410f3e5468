package io.rtaware.zenoh;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * ZettaScale's ROS 2 DDS bridge ({@code zenoh-plugin-ros2dds}, on Eclipse Cyclone DDS) running in
 * a process of its own, {@code rtaware-dds-bridge}, which this object starts and owns (issues 29
 * and 38). The bridge's Zenoh runtime listens on one endpoint; sessions that connect to it reach
 * the DDS domain it joined: the plugin maps a DDS topic {@code rt/scan} to the key {@code scan},
 * and creates DDS writers and readers for the routes that sessions announce by liveliness tokens
 * the way one bridge announces its routes to another.
 *
 * <p>A process of its own, as {@code zenoh-bridge-ros2dds} is one: the plugin reads its
 * distribution from the environment and writes {@code CYCLONEDDS_URI} into it while other threads
 * run, which inside this JVM would be undefined behaviour; the bridge process holds its sockets to
 * one network interface, which Cyclone DDS cannot be configured to do; and its DDS participant,
 * which the plugin never stops, ends with it. The process ends when the bridge is closed, and when
 * this JVM ends (its standard input closes). The executable is the file the system property
 * {@code rtaware.dds.bridge} names, else the one the build put beside the native library on the
 * class path. Thread-safe.
 */
public final class DdsBridge implements AutoCloseable {

    /** The executable's name beside the native library. */
    static final String EXECUTABLE = "rtaware-dds-bridge";
    /** How long a closed bridge may take to end before it is killed. */
    private static final long CLOSE_WAIT_MS = 5_000;

    private static final Object LOCK = new Object();
    private static Path executable;
    private static String missing;

    private final Process process;
    private final String zid;
    private final List<String> endpoints;
    private boolean closed;

    private DdsBridge(Process process, String zid, List<String> endpoints) {
        this.process = process;
        this.zid = zid;
        this.endpoints = endpoints;
    }

    /**
     * @return why the bridge cannot start in this process (the native layer is missing, or was
     *     built without the bridge), or null when it can
     */
    public static String unavailableReason() {
        String reason = ZenohLibrary.unavailableReason();
        if (reason != null) {
            return reason;
        }
        synchronized (LOCK) {
            if (executable == null && missing == null) {
                locate();
            }
            return missing;
        }
    }

    /** Finds the executable: the system property {@code rtaware.dds.bridge} (a file), else the class path. */
    private static void locate() {
        String explicit = System.getProperty("rtaware.dds.bridge");
        try {
            Path file = explicit != null && !explicit.isBlank() ? Path.of(explicit) : ZenohLibrary.extract(EXECUTABLE);
            if (file == null) {
                missing = "the native Zenoh layer was built without the ROS 2 DDS bridge (building it needs cmake and "
                        + "libclang-dev; rebuild with both installed)";
            } else if (!file.toFile().setExecutable(true, true) && !file.toFile().canExecute()) {
                missing = "the ROS 2 DDS bridge " + file + " cannot be made executable";
            } else {
                executable = file;
            }
        } catch (IOException | SecurityException e) {
            missing = "the ROS 2 DDS bridge cannot be unpacked (" + e.getMessage() + ")";
        }
    }

    /**
     * Starts the bridge's process and waits until it says it is ready: its DDS domain created and
     * its runtime listening.
     *
     * @param config what the bridge is told
     * @param startTimeoutMs how long the process may take to say so
     * @return the running bridge
     * @throws ZenohException if the bridge is not in this build, the interface has no IPv4
     *     address, or the process does not start (with its one-line reason: Cyclone DDS refusing
     *     its configuration, say)
     */
    public static DdsBridge start(DdsBridgeConfig config, long startTimeoutMs) throws ZenohException {
        String reason = unavailableReason();
        if (reason != null) {
            throw new ZenohException(reason);
        }
        List<String> command = new ArrayList<>(List.of(executable.toString(), "--listen", config.listen(),
                "--plugin-config", config.pluginConfig(), "--cyclone-config", config.cycloneConfig()));
        if (config.bindInterface() != null) {
            String address;
            try {
                address = DdsBridgeConfig.interfaceAddress(config.bindInterface());
            } catch (IllegalArgumentException e) {
                throw new ZenohException(e.getMessage());
            }
            command.addAll(List.of("--bind-interface", config.bindInterface(), "--bind-address", address));
        }
        ProcessBuilder builder = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT);
        builder.environment().remove("CYCLONEDDS_URI");
        builder.environment().putAll(config.environment());
        Process process;
        try {
            process = builder.start();
        } catch (IOException e) {
            throw new ZenohException("cannot start the ROS 2 DDS bridge " + executable + ": " + e.getMessage());
        }
        String line = firstLine(process, startTimeoutMs);
        if (line == null || !line.startsWith("ready ")) {
            process.destroyForcibly();
            String why = line == null ? "it ended without a word (status " + exitStatus(process) + ")"
                    : line.startsWith("error ") ? line.substring("error ".length()) : "it said '" + line + "'";
            throw new ZenohException("the ROS 2 DDS bridge did not start: " + why);
        }
        List<String> words = Arrays.asList(line.split(" "));
        return new DdsBridge(process, words.get(1), List.copyOf(words.subList(2, words.size())));
    }

    /** The first line of the process's output, or null when it ends first or says nothing in time. */
    private static String firstLine(Process process, long timeoutMs) throws ZenohException {
        BufferedReader out = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        CompletableFuture<String> line = CompletableFuture.supplyAsync(() -> {
            try {
                return out.readLine();
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        });
        try {
            return line.get(timeoutMs, TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            process.destroyForcibly();
            throw new ZenohException("the ROS 2 DDS bridge did not start within " + timeoutMs + " ms");
        } catch (ExecutionException e) {
            process.destroyForcibly();
            throw new ZenohException("reading the ROS 2 DDS bridge's output: " + e.getCause().getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            process.destroyForcibly();
            throw new ZenohException("interrupted while the ROS 2 DDS bridge started");
        }
    }

    private static String exitStatus(Process process) {
        try {
            return process.waitFor(1, TimeUnit.SECONDS) ? Integer.toString(process.exitValue()) : "unknown";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "unknown";
        }
    }

    /** @return the Zenoh id of the bridge's runtime (lowercase hexadecimal) */
    public String zid() {
        return zid;
    }

    /** @return the process id of the bridge's process */
    public long pid() {
        return process.pid();
    }

    /** @return the endpoints its runtime listens on, as Zenoh prints them ({@code tcp/127.0.0.1:40123}) */
    public List<String> endpoints() {
        return endpoints;
    }

    /**
     * @return the first endpoint a session on this machine can connect to
     * @throws IllegalStateException if the runtime listens on none
     */
    public String endpoint() {
        return endpoints.stream().filter(e -> e.startsWith("tcp/")).findFirst()
                .orElseThrow(() -> new IllegalStateException("the DDS bridge listens on no TCP endpoint: " + endpoints));
    }

    /**
     * Ends the bridge: its standard input is closed, on which it closes its runtime and exits; a
     * process still running {@value #CLOSE_WAIT_MS} ms later is killed. Idempotent; waits
     * uninterruptibly (an interrupt stays pending).
     *
     * @throws ZenohException if the process had to be killed, or exited with an error
     */
    @Override
    public synchronized void close() throws ZenohException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            process.getOutputStream().close();
        } catch (IOException e) {
            // the process is gone already: waiting below says how it ended
        }
        boolean interrupted = false;
        long deadlineNs = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(CLOSE_WAIT_MS);
        while (process.isAlive() && deadlineNs - System.nanoTime() > 0) {
            try {
                process.waitFor(deadlineNs - System.nanoTime(), TimeUnit.NANOSECONDS);
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        if (process.isAlive()) {
            process.destroyForcibly();
            throw new ZenohException("the ROS 2 DDS bridge (pid " + process.pid() + ") did not end within "
                    + CLOSE_WAIT_MS + " ms of being closed and was killed");
        }
        if (process.exitValue() != 0) {
            throw new ZenohException("the ROS 2 DDS bridge (pid " + process.pid() + ") exited with status "
                    + process.exitValue());
        }
    }
}
