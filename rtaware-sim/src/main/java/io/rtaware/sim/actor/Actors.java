package io.rtaware.sim.actor;

import io.rtaware.robot.geometry.Point2d;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Where every actor of a scenario is at a world time. {@link #update(long, double, double)}
 * places each actor: its position is a closed-form function of the world time and its start
 * time (the arc length {@code speed x (t - start)} along its path), so it is exact on any
 * step, and the same seed, the same steps and the same robot path give the same starts. A body
 * that starts when the robot comes near starts at the first update that finds the robot within
 * its distance. Queries ({@link #clearanceM(double, double)}, {@link #castM}) see the actors
 * present at the last update. Allocation-free after construction. Not thread-safe: the world
 * that owns it is.
 */
public final class Actors {

    private static final long JITTER_SEED_SALT = 0x632BE59BD9B4E019L;

    private final List<ActorSpec> specs;
    private final long[] startNs;
    private final long[] jitterNs;
    private final long[] appearNs;
    private final double[] passM;
    private final double[] xM;
    private final double[] yM;
    private final double[] vxMps;
    private final double[] vyMps;
    private final boolean[] present;
    private long timeNs = -1;

    /**
     * Places every actor at the start of its path, absent until the first update.
     *
     * @param specs the scenario's actors
     * @param seed the run's seed: draws each body's start jitter
     */
    public Actors(List<ActorSpec> specs, long seed) {
        this.specs = List.copyOf(specs);
        int n = this.specs.size();
        startNs = new long[n];
        jitterNs = new long[n];
        appearNs = new long[n];
        passM = new double[n];
        xM = new double[n];
        yM = new double[n];
        vxMps = new double[n];
        vyMps = new double[n];
        present = new boolean[n];
        SplittableRandom random = new SplittableRandom(seed ^ JITTER_SEED_SALT);
        for (int i = 0; i < n; i++) {
            ActorSpec s = this.specs.get(i);
            double u = random.nextDouble(); // drawn for every actor, so one actor's jitter does not shift another's
            jitterNs[i] = Math.round(s.startJitterS() * u * 1e9);
            startNs[i] = s.startWithinM() > 0 ? Long.MAX_VALUE : Math.round(s.startAtS() * 1e9) + jitterNs[i];
            appearNs[i] = Math.round(s.appearAtS() * 1e9);
            passM[i] = s.passLengthM();
            xM[i] = s.path().get(0).xM();
            yM[i] = s.path().get(0).yM();
        }
    }

    /** @return no actors */
    public static Actors none() {
        return new Actors(List.of(), 0L);
    }

    /** @return true if there are no actors at all */
    public boolean isEmpty() {
        return specs.isEmpty();
    }

    /** @return the number of actors */
    public int size() {
        return specs.size();
    }

    /**
     * @param i an actor's index
     * @return its specification
     */
    public ActorSpec spec(int i) {
        return specs.get(i);
    }

    /**
     * Places every actor at world time {@code nowNs}, starting bodies whose time has come or
     * that the robot has come near.
     *
     * @param nowNs world nanoseconds since the world was made
     * @param robotXM the robot's true x, metres
     * @param robotYM the robot's true y, metres
     */
    public void update(long nowNs, double robotXM, double robotYM) {
        timeNs = nowNs;
        for (int i = 0; i < specs.size(); i++) {
            ActorSpec s = specs.get(i);
            present[i] = nowNs >= appearNs[i];
            if (startNs[i] == Long.MAX_VALUE && present[i]
                    && Math.hypot(robotXM - xM[i], robotYM - yM[i]) <= s.startWithinM()) {
                startNs[i] = nowNs + jitterNs[i];
            }
            place(i, s, nowNs);
        }
    }

    private void place(int i, ActorSpec s, long nowNs) {
        List<Point2d> path = s.path();
        if (!s.moves() || nowNs <= startNs[i]) {
            xM[i] = path.get(0).xM();
            yM[i] = path.get(0).yM();
            vxMps[i] = 0;
            vyMps[i] = 0;
            return;
        }
        double travelled = s.speedMps() * ((nowNs - startNs[i]) * 1e-9);
        double pass = passM[i];
        boolean backwards = false;
        double along;
        switch (s.repeat()) {
            case ONCE -> along = Math.min(travelled, pass);
            case LOOP -> along = travelled % pass;
            default -> {
                double cycle = travelled % (2 * pass);
                backwards = cycle > pass;
                along = backwards ? 2 * pass - cycle : cycle;
            }
        }
        boolean stopped = s.repeat() == ActorSpec.Repeat.ONCE && travelled >= pass;
        int points = path.size();
        int segments = s.repeat() == ActorSpec.Repeat.LOOP ? points : points - 1;
        for (int k = 0; k < segments; k++) {
            Point2d a = path.get(k);
            Point2d b = path.get((k + 1) % points);
            double len = a.distanceTo(b);
            if (along <= len || k == segments - 1) {
                double f = len == 0 ? 0 : Math.min(1.0, along / len);
                xM[i] = a.xM() + (b.xM() - a.xM()) * f;
                yM[i] = a.yM() + (b.yM() - a.yM()) * f;
                double sign = stopped || len == 0 ? 0 : backwards ? -1 : 1;
                vxMps[i] = sign * s.speedMps() * (b.xM() - a.xM()) / Math.max(len, 1e-12);
                vyMps[i] = sign * s.speedMps() * (b.yM() - a.yM()) / Math.max(len, 1e-12);
                return;
            }
            along -= len;
        }
    }

    /**
     * @param xM a point's x, metres
     * @param yM a point's y, metres
     * @return the distance from the point to the nearest present actor's outline, metres (0
     *     inside one); {@link Double#POSITIVE_INFINITY} if none is present
     */
    public double clearanceM(double xM, double yM) {
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < specs.size(); i++) {
            if (present[i]) {
                best = Math.min(best, specs.get(i).shape().clearanceM(xM - this.xM[i], yM - this.yM[i]));
            }
        }
        return best;
    }

    /**
     * @param xM ray origin x, metres
     * @param yM ray origin y, metres
     * @param dirX x of the unit direction
     * @param dirY y of the unit direction
     * @param maxRangeM the range beyond which nothing is looked for
     * @return the distance to the first present actor along the ray, or {@code maxRangeM} if
     *     none is nearer
     */
    public double castM(double xM, double yM, double dirX, double dirY, double maxRangeM) {
        double best = maxRangeM;
        for (int i = 0; i < specs.size(); i++) {
            if (present[i]) {
                double ox = xM - this.xM[i];
                double oy = yM - this.yM[i];
                double reach = best + specs.get(i).shape().boundingRadiusM();
                if (ox * ox + oy * oy > reach * reach) {
                    continue; // too far to be nearer than the best so far
                }
                best = Math.min(best, specs.get(i).shape().castM(ox, oy, dirX, dirY));
            }
        }
        return best;
    }

    /** @return the world time of the last update, ns, or -1 before the first */
    public long timeNs() {
        return timeNs;
    }

    /**
     * @param i an actor's index
     * @return its x at the last update, metres
     */
    public double xM(int i) {
        return xM[i];
    }

    /**
     * @param i an actor's index
     * @return its y at the last update, metres
     */
    public double yM(int i) {
        return yM[i];
    }

    /**
     * @param i an actor's index
     * @return its velocity's x at the last update, m/s
     */
    public double vxMps(int i) {
        return vxMps[i];
    }

    /**
     * @param i an actor's index
     * @return its velocity's y at the last update, m/s
     */
    public double vyMps(int i) {
        return vyMps[i];
    }

    /**
     * @param i an actor's index
     * @return true if it was there at the last update
     */
    public boolean present(int i) {
        return present[i];
    }

    /**
     * @param i an actor's index
     * @return true if the body has started moving (always false for doors and obstacles)
     */
    public boolean started(int i) {
        return specs.get(i).moves() && timeNs > startNs[i];
    }

    /**
     * @param name an actor's name
     * @return its index, or -1 if no actor has that name
     */
    public int indexOf(String name) {
        for (int i = 0; i < specs.size(); i++) {
            if (specs.get(i).name().equals(name)) {
                return i;
            }
        }
        return -1;
    }
}
