package io.rtaware.rt;

import java.io.FileOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Optional;

/**
 * A Linux PM QoS request for the CPUs' wake-up latency, held for the length of a run: while
 * {@code /dev/cpu_dma_latency} is open with a value written to it, the kernel keeps every CPU
 * out of idle states that take longer than that to leave; the request ends when the file is
 * closed (the kernel's PM QoS interface, {@code Documentation/power/pm_qos_interface.rst}).
 * cyclictest holds 0 us this way by default; so does {@code --realtime} here.
 *
 * <p>Why: on the development VM (issue 16) an idle vCPU took about 20 us longer to wake, so a
 * SCHED_FIFO task at 1 ms measured p50 / p99 lateness of 40-43 / 100-126 us against
 * cyclictest's 21 / 51-60 us; holding 0 us gave 21 / 28 us, and cyclictest run without its
 * request ({@code --laptop}) gave 42 us on average. The cost is power: idle CPUs stay in their
 * shallowest state (or poll) for the length of the run.
 *
 * <p>Not thread-safe: opened and closed by the command that runs.
 */
public final class CpuLatencyRequest implements AutoCloseable {

    /** The kernel's device for CPU wake-up latency requests. */
    public static final Path DEVICE = Path.of("/dev/cpu_dma_latency");

    private final FileOutputStream request;
    private final int latencyUs;

    private CpuLatencyRequest(FileOutputStream request, int latencyUs) {
        this.request = request;
        this.latencyUs = latencyUs;
    }

    /**
     * Opens the device and writes the request, which holds until {@link #close()}.
     *
     * @param device the device ({@link #DEVICE}; tests pass a plain file)
     * @param latencyUs the longest wake-up latency to allow, microseconds (0: the shallowest idle state)
     * @param err where the one line goes if the request cannot be made (no such device, no
     *     permission: the run goes on with the CPUs' usual idle states)
     * @return the request, or empty if it could not be made
     */
    public static Optional<CpuLatencyRequest> hold(Path device, int latencyUs, PrintStream err) {
        if (latencyUs < 0) {
            throw new IllegalArgumentException("a latency request must be 0 us or more, got " + latencyUs);
        }
        FileOutputStream out = null;
        try {
            out = new FileOutputStream(device.toFile());
            // The binary form: one signed 32-bit value in the machine's byte order (all zero
            // bytes read the same in either order; other values are written little-endian, the
            // order of every machine this runs on).
            out.write(new byte[] {(byte) latencyUs, (byte) (latencyUs >>> 8), (byte) (latencyUs >>> 16),
                    (byte) (latencyUs >>> 24)});
            out.flush();
            return Optional.of(new CpuLatencyRequest(out, latencyUs));
        } catch (IOException | SecurityException e) {
            closeQuietly(out);
            err.println("rtaware: --realtime could not keep the CPUs out of deep idle (" + device + ": "
                    + e.getMessage() + "); wake-ups from an idle CPU stay slower");
            return Optional.empty();
        }
    }

    /** @return the latency held, microseconds */
    public int latencyUs() {
        return latencyUs;
    }

    /** Ends the request: the CPUs may use their deeper idle states again. */
    @Override
    public void close() {
        closeQuietly(request);
    }

    private static void closeQuietly(FileOutputStream out) {
        if (out == null) {
            return;
        }
        try {
            out.close();
        } catch (IOException ignored) {
            // Closing a device file that was written: nothing to do if it fails, the kernel
            // drops the request when the process exits.
        }
    }
}
