package io.rtaware.sim.server;

import java.lang.System.Logger.Level;
import java.util.function.LongFunction;
import java.util.function.Supplier;

/**
 * A failure that may repeat many times a second (accept errors, refused clients): logged once
 * when an episode starts and once when it ends, with the count, never once per occurrence. Not
 * thread-safe (one thread reports).
 */
final class FailureEpisode {

    private final System.Logger log;
    private long failures;

    FailureEpisode(System.Logger log) {
        this.log = log;
    }

    /** @param firstLine the warning logged if this failure starts an episode */
    void failed(Supplier<String> firstLine) {
        if (failures++ == 0) {
            log.log(Level.WARNING, firstLine.get());
        }
    }

    /** @param endLine the line logged, given the episode's failure count, if an episode was running */
    void ended(LongFunction<String> endLine) {
        if (failures > 0) {
            log.log(Level.INFO, endLine.apply(failures));
            failures = 0;
        }
    }
}
