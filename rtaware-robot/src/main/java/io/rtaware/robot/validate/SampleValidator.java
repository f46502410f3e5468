package io.rtaware.robot.validate;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import java.util.Locale;

/**
 * Applies {@link SampleChecks} to one device's stream of samples: remembers the last accepted
 * timestamp (so time may not run backwards), and counts accepted and rejected samples. A data
 * task decodes each sample into a scratch buffer, asks {@link #acceptOdometry} or
 * {@link #acceptScan}, and commits the sample only on {@code true}. Written by one thread (the
 * task's); the counters and the last rejection may be read from any thread.
 *
 * <p>Time: a sample whose values pass {@link SampleChecks} is still rejected when its timestamp
 * is earlier than the previous accepted one's, or more than {@link #MAX_FORWARD_JUMP_S} after
 * it (one sample stamped far ahead must not make every genuine one after it "earlier"). Both
 * rules yield to a source whose clock really restarted or jumped (a simulator started again with
 * simulated time): when {@link #EPOCH_AFTER_SAMPLES} samples in a row were rejected for their
 * timestamp alone and agree with each other (each not earlier than the one before, nor more than
 * the bound after it), the last of them is accepted and starts a new epoch of the source's clock,
 * counted ({@link #clockEpochs()}) and described ({@link #lastClockEpoch()}). {@link #restart()}
 * (a new connection) forgets the clock at once.
 */
public final class SampleValidator {

    /** The largest step forward of a device's timestamps between two accepted samples: 10 s. */
    public static final double MAX_FORWARD_JUMP_S = 10.0;
    /** Samples in a row, rejected for their time and agreeing with each other, that make a new epoch: 3. */
    public static final int EPOCH_AFTER_SAMPLES = 3;

    private final String device;
    private final SampleLimits limits;
    private double lastTimeS = Double.NaN;
    /** samples in a row rejected for their time alone that agree with each other (0: none) */
    private int candidateSamples;
    private double candidateFirstS;
    private double candidateLastS;
    private volatile long clockEpochs;
    private volatile String lastClockEpoch;
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
        String bad = SampleChecks.odometry(o, Double.NaN, limits);
        return record(bad != null ? bad : followClock(o.serverTimeS), o.serverTimeS);
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
        String bad = SampleChecks.scan(s, Double.NaN, limits);
        return record(bad != null ? bad : followClock(s.serverTimeS), s.serverTimeS);
    }

    /**
     * The timestamp rule for a sample whose values are plausible (its time finite and not
     * negative): null to accept it, else why not; tracks the candidate of a new epoch.
     */
    private String followClock(double timeS) {
        if (Double.isNaN(lastTimeS) || (timeS >= lastTimeS && timeS - lastTimeS <= MAX_FORWARD_JUMP_S)) {
            candidateSamples = 0;
            return null;
        }
        String reason = timeS < lastTimeS ? SampleChecks.timestamp(timeS, lastTimeS)
                : String.format(Locale.ROOT, "timestamp = %s s is %s s after the previous sample's %s s, more than %s s",
                        timeS, timeS - lastTimeS, lastTimeS, MAX_FORWARD_JUMP_S);
        if (candidateSamples > 0 && timeS >= candidateLastS && timeS - candidateLastS <= MAX_FORWARD_JUMP_S) {
            candidateSamples++;
        } else {
            candidateSamples = 1;
            candidateFirstS = timeS;
        }
        candidateLastS = timeS;
        if (candidateSamples < EPOCH_AFTER_SAMPLES) {
            return reason;
        }
        clockEpochs++;
        lastClockEpoch = String.format(Locale.ROOT, "%s: clock epoch %d from %s s (the previous sample was at %s s; "
                + "%d samples in a row agreed)", device, clockEpochs + 1, candidateFirstS, lastTimeS, candidateSamples);
        candidateSamples = 0;
        return null;
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
        candidateSamples = 0;
        lastRejected = false;
    }

    /** @return new epochs of the source's clock followed so far (not counting restarts) */
    public long clockEpochs() {
        return clockEpochs;
    }

    /**
     * @return one line describing the newest epoch of the source's clock (device, where it
     *     started, where the previous one ended), or null if there was none
     */
    public String lastClockEpoch() {
        return lastClockEpoch;
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
