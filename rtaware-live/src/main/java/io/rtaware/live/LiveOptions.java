package io.rtaware.live;

import java.util.Objects;

/**
 * Whether and where to serve the live view.
 *
 * @param enabled serve it at all
 * @param bindAddress address to listen on ({@value #LOOPBACK} unless the user exposes it)
 * @param port TCP port, 0 for a free one
 * @param lingerNs wall time to keep serving the final page after the run has ended
 */
public record LiveOptions(boolean enabled, String bindAddress, int port, long lingerNs) {

    /** The default bind address: this machine only. */
    public static final String LOOPBACK = "127.0.0.1";

    /**
     * Validates the fields.
     *
     * @param enabled serve it at all
     * @param bindAddress address to listen on ({@value #LOOPBACK} unless the user exposes it)
     * @param port TCP port, 0 for a free one
     * @param lingerNs wall time to keep serving the final page after the run has ended
     */
    public LiveOptions {
        Objects.requireNonNull(bindAddress, "bindAddress");
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("--live-port must be 0..65535, got " + port);
        }
        if (lingerNs < 0) {
            throw new IllegalArgumentException("--live-linger must not be negative");
        }
    }

    /**
     * The live view on this machine only, as a program's own {@code main} serves it.
     *
     * @param port TCP port of {@value #LOOPBACK}, 0 for a free one
     * @return options serving on {@value #LOOPBACK}:{@code port}, not lingering after the run
     * @throws IllegalArgumentException if the port is not 0..65535
     */
    public static LiveOptions loopback(int port) {
        return new LiveOptions(true, LOOPBACK, port, 0);
    }

    /** @return options with the live view off */
    public static LiveOptions off() {
        return new LiveOptions(false, LOOPBACK, 0, 0);
    }
}
