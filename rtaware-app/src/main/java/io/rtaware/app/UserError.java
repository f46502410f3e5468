package io.rtaware.app;

/**
 * A mistake in what the user asked for (a bad flag value, a missing file, an unreachable
 * server): printed as one line naming the problem and the value, exit status 2, no stack trace.
 */
public final class UserError extends RuntimeException {

    /** @param message one line naming the problem and the offending value */
    public UserError(String message) {
        super(message, null, false, false);
    }
}
