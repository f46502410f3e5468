package io.rtaware.core.monitor;

/**
 * How a cycle ended, for recorders of every cycle ({@link MonitorListener#onCycleRecord}). When
 * several apply, the first in this order wins: error, miss, stale, ok.
 */
public enum CycleOutcome {
    /** Finished by its deadline, read new data, did not throw. */
    OK,
    /** Finished after its deadline (or was claimed by the watchdog as missed while running). */
    MISS,
    /** None of its inputs had new data. */
    STALE,
    /** The cycle threw; nothing it published was committed. */
    ERROR
}
