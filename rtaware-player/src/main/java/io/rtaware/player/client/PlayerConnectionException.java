package io.rtaware.player.client;

import java.io.IOException;

/**
 * The connection to the Player server could not be made or was lost. Immutable and
 * thread-safe.
 */
public class PlayerConnectionException extends IOException {

    private static final long serialVersionUID = 1L;

    /**
     * @param message what happened, naming the server
     * @param cause the underlying failure, or null
     */
    public PlayerConnectionException(String message, Throwable cause) {
        super(message, cause);
    }
}
