package io.rtaware.record.mcap;

import java.io.IOException;

/** A file that is not valid MCAP, or that fails a CRC check. */
public final class McapFormatException extends IOException {

    private static final long serialVersionUID = 1L;

    /** @param message what is wrong and where */
    public McapFormatException(String message) {
        super(message);
    }
}
