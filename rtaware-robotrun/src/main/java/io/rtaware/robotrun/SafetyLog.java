package io.rtaware.robotrun;

import io.rtaware.record.RunRecorder;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.world.World;
import java.util.Locale;

/**
 * The run's safety events as log lines on the recording's {@code /rosout} (and so live on a
 * Foxglove tap): each collision and near miss the built-in simulator counts, as
 * {@link NavRun#superviseUntilEnd}'s looks see it (so up to one look late), and how the run
 * ended, fatal when it ended on an error (a safety fault of the robot's data, a lost robot).
 * Part of every {@link NavRun} given a recorder; the supervising thread only.
 */
final class SafetyLog {

    /** The logger name of the lines. */
    static final String NAME = "safety";

    private final RunRecorder recorder;
    private final PlayerSimServer simulator;
    private long collisions;
    private long nearMisses;

    /**
     * @param recorder the recording, or null (then nothing is logged)
     * @param simulator the built-in simulator, or null for another robot (then only the ending is logged)
     */
    SafetyLog(RunRecorder recorder, PlayerSimServer simulator) {
        this.recorder = recorder;
        this.simulator = simulator;
    }

    /**
     * Logs the collisions and near misses counted since the last poll.
     *
     * @param nowNs world time now
     */
    void poll(long nowNs) {
        if (recorder == null || simulator == null) {
            return;
        }
        long[] counts = simulator.withWorld(w -> new long[] {w.contactCount(), w.nearMisses()});
        if (counts[0] > collisions) {
            collisions = counts[0];
            recorder.log(RunRecorder.ERROR_LEVEL, nowNs, NAME, "collision: the robot touched an obstacle ("
                    + collisions + " so far)");
        }
        if (counts[1] > nearMisses) {
            nearMisses = counts[1];
            recorder.log(RunRecorder.WARN, nowNs, NAME, String.format(Locale.ROOT,
                    "near miss: the robot came within %.2f m of an obstacle without touching it (%d so far)",
                    World.NEAR_MISS_MARGIN_M, nearMisses));
        }
    }

    /**
     * Logs how the run ended.
     *
     * @param ending the ending
     * @param nowNs world time now
     */
    void ended(RunState.Ending ending, long nowNs) {
        if (recorder == null) {
            return;
        }
        boolean error = ending.outcome() == RunOutcome.ERROR;
        recorder.log(error ? RunRecorder.FATAL : RunRecorder.INFO, nowNs, NAME,
                "run ended, " + ending.outcome().jsonName() + ": " + ending.reason() + (error ? "; stopping the robot" : ""));
    }
}
