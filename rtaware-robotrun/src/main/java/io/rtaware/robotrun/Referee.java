package io.rtaware.robotrun;

import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.monitor.WorldClockIdleStrategy;
import io.rtaware.core.time.Clock;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.LongSupplier;
import java.util.function.Supplier;
import org.agrona.concurrent.Agent;

/**
 * Watches the robot from outside the controller, as the paper's ground-truth sensors did: samples
 * the true pose at a fixed world-time rate on a thread of its own, records the trajectory, the
 * distance travelled and where deadline misses happened, and tells whether the robot is stuck.
 * When the source fails to give a pose after it has given one (a restarted simulator, a lost
 * connection, an impossible pose), the referee records a {@link GroundTruthGap} from the last
 * pose before the failure to the first one after it (or to the end of the run): the distance
 * travelled is summed only between samples without a gap between them, and the report says
 * which time it covers. A sampling thread that merely ran late (a loaded machine) is no gap.
 * The sampling thread ({@value #THREAD_NAME}) is an {@link AgentThread} that waits for the next
 * sample's world time with a {@link WorldClockIdleStrategy}: a sample that throws
 * (a fault of ours, not of the pose source, whose failures are gaps) is counted, recorded as a
 * failed sample (a gap, {@link #lastError()}), the first one printed to standard error, and the
 * sampling goes on. Thread-safe: sampled by its own thread, read by any.
 */
public final class Referee implements AutoCloseable {

    /** Where the true pose comes from. */
    public interface PoseSource extends AutoCloseable {
        /**
         * @return the robot's pose now, or null if none is known yet
         * @throws Exception if the source failed (the referee records a gap)
         */
        Pose2d pose() throws Exception;

        /** @return {@code ground_truth} or {@code odometry}, as the report says */
        public String kind();

        @Override
        default void close() throws Exception {
        }
    }

    /**
     * One sample of the path.
     *
     * @param tS world seconds since the run started
     * @param pose the pose
     * @param believed the robot's own estimate of its pose then (its odometry), or null if unknown
     */
    public record Sample(double tS, Pose2d pose, Pose2d believed) {
    }

    /** The name of the sampling thread. */
    public static final String THREAD_NAME = "rtaware-referee";

    private final Clock clock;
    private final long startNs;
    private final long samplePeriodNs;
    private final PoseSource source;
    private final LongSupplier misses;
    private final Supplier<Pose2d> believed;
    private final List<Sample> samples = new ArrayList<>();
    private final List<Point2d> missMarkers = new ArrayList<>();
    private final List<GroundTruthGap> gaps = new ArrayList<>();
    /** The sampling loop, once started. */
    private volatile AgentThread sampler;
    /** How the sampling loop waits for the next sample, once started. */
    private volatile WorldClockIdleStrategy samplerIdle;
    private double travelledM;
    private long lastMisses;
    private String lastError;
    /** True from a failed sample until the next pose: a gap is open. */
    private boolean failing;

    /**
     * @param clock world clock
     * @param startNs world time of the run's start
     * @param samplePeriodNs world time between samples
     * @param source the pose source; closed with the referee
     * @param misses the total deadline misses so far; a marker is recorded where it grows
     */
    public Referee(Clock clock, long startNs, long samplePeriodNs, PoseSource source, LongSupplier misses) {
        this(clock, startNs, samplePeriodNs, source, misses, () -> null);
    }

    /**
     * @param clock world clock
     * @param startNs world time of the run's start
     * @param samplePeriodNs world time between samples
     * @param source the pose source; closed with the referee
     * @param misses the total deadline misses so far; a marker is recorded where it grows
     * @param believed the robot's own pose estimate now (its odometry), or null while unknown;
     *     recorded beside each true pose
     */
    public Referee(Clock clock, long startNs, long samplePeriodNs, PoseSource source, LongSupplier misses,
            Supplier<Pose2d> believed) {
        this.believed = Objects.requireNonNull(believed, "believed");
        this.clock = clock;
        this.startNs = startNs;
        this.samplePeriodNs = samplePeriodNs;
        this.source = Objects.requireNonNull(source, "source");
        this.misses = misses;
    }

    /**
     * Starts sampling on the referee's own thread, every {@code samplePeriodNs} of world time.
     *
     * @return this referee
     */
    public Referee start() {
        WorldClockIdleStrategy idle = new WorldClockIdleStrategy(clock);
        samplerIdle = idle;
        sampler = AgentThread.start(new Sampler(idle), idle, this::samplingFailed);
        return this;
    }

    /** @return how the sampling thread waits, once started (tests step it on a manual clock) */
    WorldClockIdleStrategy samplerIdle() {
        return samplerIdle;
    }

    /**
     * The sampling loop: a sample when the next one is due in world time, else no work and the
     * idle waits for that time; a loop that fell behind samples at once and goes on from there.
     */
    private final class Sampler implements Agent {
        private final WorldClockIdleStrategy idle;
        /** World time of the next sample (the sampling thread only). */
        private long nextNs;

        Sampler(WorldClockIdleStrategy idle) {
            this.idle = idle;
        }

        @Override
        public void onStart() {
            nextNs = clock.nanos();
        }

        @Override
        public int doWork() {
            long nowNs = clock.nanos();
            if (nextNs - nowNs > 0) {
                idle.wakeAt(nextNs);
                return 0;
            }
            // The next sample is set before this one is taken, so a sample that throws does not repeat at once.
            nextNs += samplePeriodNs;
            if (nextNs - nowNs <= 0) {
                nextNs = nowNs;
            }
            sample();
            return 1;
        }

        @Override
        public String roleName() {
            return THREAD_NAME;
        }
    }

    /** A sample threw: a failed sample (a gap), counted by the sampler; the first one is printed. */
    private void samplingFailed(Throwable error) {
        synchronized (this) {
            lastError = String.valueOf(error);
            failing = true;
        }
        AgentThread loop = sampler;
        if (loop == null || loop.errors() <= 1) {
            System.err.println("rtaware run: referee: a ground-truth sample failed: " + error
                    + " (recorded as a gap; further failures are counted)");
        }
    }

    /** @return samples that threw on the sampling thread so far (failures of the pose source are not counted here) */
    public long samplingErrors() {
        AgentThread loop = sampler;
        return loop == null ? 0 : loop.errors();
    }

    /** Takes one sample now (the sampling thread's step; tests call it on a manual clock). */
    public void sample() {
        Pose2d pose;
        try {
            pose = source.pose();
        } catch (Exception e) {
            synchronized (this) {
                lastError = e.getMessage();
                failing = true;
            }
            return;
        }
        if (pose == null) {
            synchronized (this) {
                failing = true;
            }
            return;
        }
        double tS = (clock.nanos() - startNs) / 1e9;
        long missesNow = misses.getAsLong();
        Pose2d believedNow = believed.get();
        synchronized (this) {
            if (!samples.isEmpty()) {
                Sample previous = samples.get(samples.size() - 1);
                if (failing) {
                    gaps.add(new GroundTruthGap(previous.tS(), tS, false));
                } else {
                    travelledM += previous.pose().distanceTo(pose);
                }
            }
            failing = false;
            samples.add(new Sample(tS, pose, believedNow));
            if (missesNow > lastMisses) {
                missMarkers.add(pose.position());
                lastMisses = missesNow;
            }
        }
    }

    /** @return {@code ground_truth} or {@code odometry} */
    public String kind() {
        return source.kind();
    }

    /** @return the latest pose, or null if none yet */
    public synchronized Pose2d latest() {
        return samples.isEmpty() ? null : samples.get(samples.size() - 1).pose();
    }

    /**
     * @return the latest pose if it is the truth now: the source measures the true pose (kind
     *     {@code ground_truth}) and no gap is open (it has not failed since); else null
     */
    public synchronized Pose2d latestTrue() {
        return failing || samples.isEmpty() || !"ground_truth".equals(source.kind()) ? null
                : samples.get(samples.size() - 1).pose();
    }

    /**
     * @param endS world seconds since the start at which the run ended
     * @return the gaps in the measurement, including one still open at {@code endS}
     */
    public synchronized List<GroundTruthGap> gaps(double endS) {
        List<GroundTruthGap> all = new ArrayList<>(gaps);
        if (failing || samples.isEmpty()) {
            all.add(new GroundTruthGap(samples.isEmpty() ? 0.0 : samples.get(samples.size() - 1).tS(), endS, true));
        }
        return all;
    }

    /** @return metres travelled so far, summed over the spans without a gap */
    public synchronized double travelledM() {
        return travelledM;
    }

    /** @return a copy of the samples so far */
    public synchronized List<Sample> samples() {
        return new ArrayList<>(samples);
    }

    /** @return where deadline misses happened */
    public synchronized List<Point2d> missMarkers() {
        return new ArrayList<>(missMarkers);
    }

    /** @return the last error of the pose source, or null */
    public synchronized String lastError() {
        return lastError;
    }

    /**
     * @param windowS world seconds to look back
     * @return how far the robot moved in the last {@code windowS} seconds (straight line), or
     *     {@link Double#NaN} if the run is younger than the window
     */
    public synchronized double displacementOverLastM(double windowS) {
        if (samples.isEmpty()) {
            return Double.NaN;
        }
        Sample last = samples.get(samples.size() - 1);
        for (int i = samples.size() - 1; i >= 0; i--) {
            if (last.tS() - samples.get(i).tS() >= windowS) {
                return samples.get(i).pose().distanceTo(last.pose());
            }
        }
        return Double.NaN;
    }

    /** Stops sampling (waking and joining the sampling thread), takes a last sample and closes the source. */
    @Override
    public void close() {
        AgentThread loop = sampler;
        if (loop != null) {
            loop.close();
        }
        sample();
        try {
            source.close();
        } catch (Exception ignored) {
            // The run is over; a failing close of the observer's connection changes nothing.
        }
    }
}
