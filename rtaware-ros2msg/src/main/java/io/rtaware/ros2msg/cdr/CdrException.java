package io.rtaware.ros2msg.cdr;

/**
 * A CDR buffer that cannot be read or written: truncated input, a length from the wire larger
 * than what is left of the buffer, an unsupported encapsulation, or a message larger than the
 * writer's capacity.
 */
public final class CdrException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /** @param message what is wrong, naming the offending value */
    public CdrException(String message) {
        super(message);
    }
}
