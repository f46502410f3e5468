package io.rtaware.robotrun;

import io.rtaware.core.report.Rounding;
import io.rtaware.core.time.Clock;
import java.util.Locale;
import java.util.function.LongSupplier;

/**
 * Decides, one look at a time, whether a robot run is over and why: the finish reached (by
 * the robot's own estimate, its odometry, as the paper counts it; the reason also says how far
 * the true pose was from the finish then, where ground truth exists), the time limit passed, the robot stuck (commanded to move, moved less than
 * {@link #STUCK_MIN_MOVE_M} in the stuck window), the robot server lost (no odometry for
 * {@link #LOST_SERVER_AFTER_S} of world time and {@link #LOST_SERVER_AFTER_WALL_S} of wall time),
 * or a safety fault (a device sent only impossible data). World time comes from the monitor's
 * clock, wall time from an injected source, so every rule is tested without sleeping. Not
 * thread-safe: the supervising thread owns it.
 */
public final class Supervisor {

    /** Least displacement over the stuck window for a commanded robot to count as moving. */
    public static final double STUCK_MIN_MOVE_M = 0.05;
    /** World time without odometry after which the server counts as lost. */
    public static final double LOST_SERVER_AFTER_S = 5.0;
    /** Also required, so a loaded machine that stalls the scaled world briefly is not a lost server. */
    public static final double LOST_SERVER_AFTER_WALL_S = 3.0;

    /** What the supervisor looks at; each call reads the newest state. */
    public interface View {
        /** Reads the newest state once per look; the other methods answer from it. */
        void refresh();

        /** @return true once the controller's course status says every waypoint was reached */
        boolean courseDone();

        /** @return the odometry key's generation (grows with every commit) */
        long odometryGeneration();

        /** @return true if the newest odometry says the robot is pushing against something */
        boolean stalled();

        /** @return true if the newest motor command is not a stop */
        boolean commandedToMove();

        /**
         * @param windowS world seconds to look back
         * @return straight-line displacement over the window, NaN if the run is younger
         */
        double displacementOverLastM(double windowS);

        /** @return one line describing a safety fault of the robot's data, or null */
        String safetyFault();

        /**
         * @return the distance from the robot's true pose at this look to the finish, metres, or
         *     NaN where no ground truth exists (a robot without a simulation truth source) or it
         *     is lost at this moment
         */
        double trueDistanceToFinishM();
    }

    private final View view;
    private final Clock clock;
    private final LongSupplier wallNanos;
    private final long startNs;
    private final double timeLimitS;
    private final double stuckAfterS;
    private long lastOdometryGeneration;
    private long lastOdometryNs;
    private long lastOdometryWallNs;
    private boolean wasStalled;
    private volatile long stallEdges;

    /**
     * @param view what to look at
     * @param clock the world clock
     * @param wallNanos wall time in ns (e.g. {@code System::nanoTime})
     * @param startNs world time of the run's start
     * @param timeLimitS the scenario's time limit in world seconds
     * @param stuckAfterS the stuck window in world seconds
     */
    public Supervisor(View view, Clock clock, LongSupplier wallNanos, long startNs, double timeLimitS, double stuckAfterS) {
        this.view = view;
        this.clock = clock;
        this.wallNanos = wallNanos;
        this.startNs = startNs;
        this.timeLimitS = timeLimitS;
        this.stuckAfterS = stuckAfterS;
        this.lastOdometryNs = startNs;
        this.lastOdometryWallNs = wallNanos.getAsLong();
    }

    /**
     * One look.
     *
     * @return how the run ended, or null while it goes on
     */
    public RunState.Ending check() {
        long nowNs = clock.nanos();
        long nowWallNs = wallNanos.getAsLong();
        view.refresh();
        boolean stalled = view.stalled();
        if (stalled && !wasStalled) {
            stallEdges++;
        }
        wasStalled = stalled;
        long generation = view.odometryGeneration();
        if (generation != lastOdometryGeneration) {
            lastOdometryGeneration = generation;
            lastOdometryNs = nowNs;
            lastOdometryWallNs = nowWallNs;
        }
        String fault = view.safetyFault();
        if (fault != null) {
            return new RunState.Ending(RunOutcome.ERROR, fault);
        }
        if (view.courseDone()) {
            return new RunState.Ending(RunOutcome.COMPLETED, finishReached(view.trueDistanceToFinishM()));
        }
        if ((nowNs - startNs) / 1e9 >= timeLimitS) {
            return new RunState.Ending(RunOutcome.TIMEOUT,
                    String.format(Locale.ROOT, "time limit of %.0f s passed", timeLimitS));
        }
        if (view.commandedToMove() && view.displacementOverLastM(stuckAfterS) < STUCK_MIN_MOVE_M) {
            return new RunState.Ending(RunOutcome.STUCK, String.format(Locale.ROOT,
                    "moved less than %.2f m in %.0f s while commanded to move", STUCK_MIN_MOVE_M, stuckAfterS));
        }
        if ((nowNs - lastOdometryNs) / 1e9 > LOST_SERVER_AFTER_S
                && (nowWallNs - lastOdometryWallNs) / 1e9 > LOST_SERVER_AFTER_WALL_S) {
            return new RunState.Ending(RunOutcome.ERROR, String.format(Locale.ROOT,
                    "no odometry from the robot server for %.0f s of world time (%.0f s of wall time): connection lost",
                    LOST_SERVER_AFTER_S, LOST_SERVER_AFTER_WALL_S));
        }
        return null;
    }

    /**
     * Why a completed run ended, in words that claim only what was measured: the finish is
     * reached by odometry (the controller's belief decides it), and where the true pose is known,
     * how far it was from the finish.
     *
     * The distance is first rounded to the millimetre, the resolution at which the report records
     * each waypoint pass's true distance, and only then to the two decimals shown: rounding the raw
     * value straight to two decimals could print 0.28 here beside the pass's 0.285, shown as 0.29,
     * for the same pose.
     *
     * @param trueDistanceM the true pose's distance from the finish at the ending, metres, or NaN
     *     where no ground truth exists
     * @return e.g. {@code finish reached by odometry; 1.06 m from it in truth}
     */
    public static String finishReached(double trueDistanceM) {
        return Double.isFinite(trueDistanceM)
                ? String.format(Locale.ROOT, "finish reached by odometry; %.2f m from it in truth",
                        Rounding.toDecimals(trueDistanceM, 3))
                : "finish reached by odometry";
    }

    /** @return rising edges of the stall flag seen so far (contacts, for a server without a contact count) */
    public long stallEdges() {
        return stallEdges;
    }
}
