package io.rtaware.player.client;

import java.io.IOException;

/**
 * A reply or data did not arrive in time. The message names the device and the timeout.
 * Immutable and thread-safe.
 */
public class PlayerTimeoutException extends IOException {

    private static final long serialVersionUID = 1L;

    /** @param message what timed out, naming the device and the timeout */
    public PlayerTimeoutException(String message) {
        super(message);
    }
}
