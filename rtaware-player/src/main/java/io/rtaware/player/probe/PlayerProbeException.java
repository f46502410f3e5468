package io.rtaware.player.probe;

/**
 * The probe could not run: a malformed {@code HOST:PORT}, an unreachable server, a peer that
 * is not a Player server. The message is one line meant for the user. Immutable and
 * thread-safe.
 */
public class PlayerProbeException extends Exception {

    private static final long serialVersionUID = 1L;

    /**
     * @param message one line describing the problem
     * @param cause the underlying failure, or null
     */
    public PlayerProbeException(String message, Throwable cause) {
        super(message, cause);
    }
}
