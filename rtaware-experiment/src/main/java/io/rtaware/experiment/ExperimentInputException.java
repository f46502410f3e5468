package io.rtaware.experiment;

/**
 * A mistake in what the user asked the experiment for (a bad sets file, an output folder made
 * with other settings, a run command that rejects its arguments): one line naming the file, the
 * field and the value. The command line turns it into its user-error exit.
 */
public final class ExperimentInputException extends RuntimeException {

    /** @param message one line naming the problem and the offending value */
    public ExperimentInputException(String message) {
        super(message, null, false, false);
    }
}
