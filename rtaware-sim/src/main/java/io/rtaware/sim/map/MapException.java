package io.rtaware.sim.map;

/**
 * A map file that cannot be loaded. The message is one line naming the file, the field and
 * the offending value. Immutable.
 */
public final class MapException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /** @param message one line naming the file, the field and the value */
    public MapException(String message) {
        super(message);
    }

    /**
     * @param message one line naming the file, the field and the value
     * @param cause the underlying failure
     */
    public MapException(String message, Throwable cause) {
        super(message, cause);
    }
}
