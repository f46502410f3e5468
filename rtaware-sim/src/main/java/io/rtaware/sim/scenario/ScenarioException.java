package io.rtaware.sim.scenario;

/**
 * A scenario that cannot be loaded. The message is one line naming the file, the field and
 * the offending value. Immutable.
 */
public final class ScenarioException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /** @param message one line naming the file, the field and the value */
    public ScenarioException(String message) {
        super(message);
    }

    /**
     * @param message one line naming the file, the field and the value
     * @param cause the underlying failure
     */
    public ScenarioException(String message, Throwable cause) {
        super(message, cause);
    }
}
