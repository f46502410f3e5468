package io.rtaware.robot.validate;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;

/**
 * Applies {@link SampleChecks} to one device's stream of samples: remembers the last accepted
 * timestamp (so time may not run backwards), and counts accepted and rejected samples. A data
 * task decodes each sample into a scratch buffer, asks {@link #acceptOdometry} or
 * {@link #acceptScan}, and commits the sample only on {@code true}. Written by one thread (the
 * task's); the counters and the last rejection may be read from any thread.
 */
public final class SampleValidator {

    private final String device;
    private final SampleLimits limits;
    private double lastTimeS = Double.NaN;
    private volatile long accepted;
    private volatile long rejected;
    private volatile long droppedBeams;
    private volatile boolean lastRejected;
    private volatile String lastRejection;

    /**
     * @param device the device's name in messages, e.g. {@code laser:0}
     * @param limits the bounds
     */
    public SampleValidator(String device, SampleLimits limits) {
        this.device = device;
        this.limits = limits;
    }

    /**
     * @param o a decoded position2d state with its timestamp
     * @return true if it may be committed; false if it was rejected (and counted)
     */
    public boolean acceptOdometry(Odometry o) {
        return record(SampleChecks.odometry(o, lastTimeS, limits), o.serverTimeS);
    }

    /**
     * Puts the scan's readings into the form {@link LaserScan} defines
     * ({@link SampleChecks#normalizeBeams}: beams that say nothing are dropped and counted), then
     * checks the scan as a whole.
     *
     * @param s a decoded scan with its geometry and timestamp; its readings are normalized in place
     * @return true if it may be committed; false if it was rejected (and counted)
     */
    public boolean acceptScan(LaserScan s) {
        int dropped = SampleChecks.normalizeBeams(s, limits);
        if (dropped > 0) {
            droppedBeams += dropped;
        }
        return record(SampleChecks.scan(s, lastTimeS, limits), s.serverTimeS);
    }

    /**
     * Counts a sample rejected by a check made elsewhere (e.g. a ground-truth pose).
     *
     * @param reason why it cannot be true, or null if it was accepted
     * @param timeS its timestamp (remembered when accepted), or NaN if it has none
     * @return true if accepted
     */
    public boolean record(String reason, double timeS) {
        if (reason == null) {
            if (!Double.isNaN(timeS)) {
                lastTimeS = timeS;
            }
            accepted++;
            lastRejected = false;
            return true;
        }
        rejected++;
        lastRejected = true;
        lastRejection = reason;
        return false;
    }

    /**
     * A new connection (possibly to a restarted server whose clock starts again): forgets the
     * last timestamp; the counters go on.
     */
    public void restart() {
        lastTimeS = Double.NaN;
        lastRejected = false;
    }

    /** @return the device's name */
    public String device() {
        return device;
    }

    /** @return samples accepted */
    public long accepted() {
        return accepted;
    }

    /** @return samples rejected */
    public long rejected() {
        return rejected;
    }

    /** @return beams dropped from accepted and rejected scans (NaN, or beyond the maximum range) */
    public long droppedBeams() {
        return droppedBeams;
    }

    /** @return true if the newest sample was rejected */
    public boolean lastRejected() {
        return lastRejected;
    }

    /** @return the reason of the newest rejection, or null if none yet */
    public String lastRejection() {
        return lastRejection;
    }
}
