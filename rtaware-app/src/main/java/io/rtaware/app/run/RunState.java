package io.rtaware.app.run;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;

/**
 * What a run's supervisor and its termination handler share: the start instant, the referee
 * and how the run ended. Created before the monitor starts, so a termination handler that runs
 * early (Ctrl-C during start-up, on the shutdown-hook thread) reads the creation instant and no
 * referee, never an unset field. Thread-safe: fields are volatile, the ending is set once.
 */
final class RunState {

    /**
     * How the run ended.
     *
     * @param outcome the outcome
     * @param reason why, in words
     */
    record Ending(RunOutcome outcome, String reason) {
        Ending {
            Objects.requireNonNull(outcome, "outcome");
            Objects.requireNonNull(reason, "reason");
        }
    }

    private final AtomicReference<Ending> ending = new AtomicReference<>();
    private volatile long startNs;
    private volatile Referee referee;
    private volatile Supervisor supervisor;

    /** @param createdNs world time now, the start until {@link #started} says otherwise */
    RunState(long createdNs) {
        this.startNs = createdNs;
    }

    /**
     * @param startNs world time at which the monitor started the tasks
     * @param referee the run's referee
     * @param supervisor the run's supervisor
     */
    void started(long startNs, Referee referee, Supervisor supervisor) {
        this.startNs = startNs;
        this.referee = referee;
        this.supervisor = supervisor;
    }

    /** @return rising edges of the stall flag the supervisor saw (0 before the start) */
    long stallEdges() {
        Supervisor s = supervisor;
        return s == null ? 0 : s.stallEdges();
    }

    /** @return world time of the start (the creation instant before {@link #started}) */
    long startNs() {
        return startNs;
    }

    /** @return the referee, or null before the start */
    Referee referee() {
        return referee;
    }

    /**
     * Records the ending unless one was recorded already.
     *
     * @return true if this call set it
     */
    boolean end(RunOutcome outcome, String reason) {
        return ending.compareAndSet(null, new Ending(outcome, reason));
    }

    /** @return the ending, or null while the run goes on */
    Ending ending() {
        return ending.get();
    }

    /** @return the outcome, or null while the run goes on (for the live view) */
    RunOutcome outcome() {
        Ending e = ending.get();
        return e == null ? null : e.outcome();
    }
}
