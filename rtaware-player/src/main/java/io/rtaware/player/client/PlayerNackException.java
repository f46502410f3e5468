package io.rtaware.player.client;

import java.io.IOException;

/**
 * The server refused a request: a RESP_NACK, or a subscription ACK whose access is ERROR.
 * Immutable and thread-safe.
 */
public class PlayerNackException extends IOException {

    private static final long serialVersionUID = 1L;

    /** @param message what was refused, naming the device */
    public PlayerNackException(String message) {
        super(message);
    }
}
