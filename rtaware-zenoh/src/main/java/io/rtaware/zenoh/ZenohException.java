package io.rtaware.zenoh;

import java.io.IOException;

/** A Zenoh operation failed (thrown by the native layer with Zenoh's own message). */
public final class ZenohException extends IOException {

    /**
     * @param message what failed and Zenoh's reason
     */
    public ZenohException(String message) {
        super(message);
    }
}
