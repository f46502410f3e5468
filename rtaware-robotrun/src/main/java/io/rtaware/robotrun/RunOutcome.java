package io.rtaware.robotrun;

/**
 * How a robot run ended. {@link #jsonName()} is the {@code outcome} string in {@code report.json}
 * and on the console.
 */
public enum RunOutcome {
    /** Every waypoint was reached. */
    COMPLETED("completed", 0),
    /** The scenario's time limit passed. */
    TIMEOUT("timeout", 0),
    /** The robot was commanded to move but did not. */
    STUCK("stuck", 0),
    /** Ctrl-C, SIGTERM, or the monitor stopped for another reason. */
    INTERRUPTED("interrupted", 130),
    /** The robot server was lost, or sent data that cannot be true. */
    ERROR("error", 1);

    private final String jsonName;
    private final int exitStatus;

    RunOutcome(String jsonName, int exitStatus) {
        this.jsonName = jsonName;
        this.exitStatus = exitStatus;
    }

    /** @return the name in reports, e.g. {@code completed} */
    public String jsonName() {
        return jsonName;
    }

    /** @return the process's exit status for this outcome */
    public int exitStatus() {
        return exitStatus;
    }

    @Override
    public String toString() {
        return jsonName;
    }
}
