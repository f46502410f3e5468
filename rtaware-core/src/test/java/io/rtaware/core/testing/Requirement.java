package io.rtaware.core.testing;

/**
 * Something a test needs that a machine may lack: the native Zenoh layer, the Python or npm peers,
 * a browser. Named on a test with {@link Requires}; an implementation has a public constructor
 * without parameters and looks at the machine each time it is asked.
 */
public interface Requirement {

    /** @return what is required, in the words a skipped or failed test prints */
    String name();

    /** @return why it is missing here, or {@code null} when it is present */
    String missingReason();

    /**
     * @return why CI may lack it on this machine (CI said so in the environment), or {@code null}
     *     when under {@code CI=true} its absence fails the test; none by default
     */
    default String excusedUnderCi() {
        return null;
    }
}
