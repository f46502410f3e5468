package io.rtaware.robotrun;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;

/**
 * What a run's supervisor and its termination handler share: the start instant, the referee
 * and how the run ended. Created before the monitor starts, so a termination handler that runs
 * early (Ctrl-C during start-up, on the shutdown-hook thread) reads the creation instant and no
 * referee, never an unset field. Thread-safe: fields are volatile, the ending is set once.
 */
public final class RunState {

    /**
     * How the run ended.
     *
     * @param outcome the outcome
     * @param reason why, in words
     */
    public record Ending(RunOutcome outcome, String reason) {
        /**
         * Both are required.
         *
         * @param outcome the outcome
         * @param reason why, in words
         */
        public Ending {
            Objects.requireNonNull(outcome, "outcome");
            Objects.requireNonNull(reason, "reason");
        }
    }

    private final AtomicReference<Ending> ending = new AtomicReference<>();
    private volatile long startNs;
    private volatile long endedNs;
    private volatile Referee referee;
    private volatile Supervisor supervisor;

    /** @param createdNs world time now, the start until {@link #started} says otherwise */
    public RunState(long createdNs) {
        this.startNs = createdNs;
    }

    /**
     * @param startNs world time at which the monitor started the tasks
     * @param referee the run's referee
     * @param supervisor the run's supervisor
     */
    public void started(long startNs, Referee referee, Supervisor supervisor) {
        this.startNs = startNs;
        this.referee = referee;
        this.supervisor = supervisor;
    }

    /** @return rising edges of the stall flag the supervisor saw (0 before the start) */
    public long stallEdges() {
        Supervisor s = supervisor;
        return s == null ? 0 : s.stallEdges();
    }

    /** @return world time of the start (the creation instant before {@link #started}) */
    public long startNs() {
        return startNs;
    }

    /** @return the referee, or null before the start */
    public Referee referee() {
        return referee;
    }

    /**
     * Records the ending, and when it happened, unless one was recorded already.
     *
     * @param outcome how the run ended
     * @param reason why, in words
     * @param atNs world time of the ending (when the supervisor saw the finish, the time limit, ...)
     * @return true if this call set it
     */
    public boolean end(RunOutcome outcome, String reason, long atNs) {
        if (!ending.compareAndSet(null, new Ending(outcome, reason))) {
            return false;
        }
        endedNs = atNs;
        return true;
    }

    /**
     * The run's duration in world time: from the start to the ending, not to the moment the
     * report is written. Stopping the tasks, the referee and the console takes wall time that, at
     * {@code --time-scale 10}, would add up to ten times as much world time to a run that is over.
     *
     * @param nowNs world time now, used while no ending is recorded
     * @return world nanoseconds from the start to the ending (or to now)
     */
    public long elapsedNs(long nowNs) {
        return (ending.get() == null ? nowNs : endedNs) - startNs;
    }

    /** @return the ending, or null while the run goes on */
    public Ending ending() {
        return ending.get();
    }

    /** @return the outcome, or null while the run goes on (for the live view) */
    public RunOutcome outcome() {
        Ending e = ending.get();
        return e == null ? null : e.outcome();
    }
}
