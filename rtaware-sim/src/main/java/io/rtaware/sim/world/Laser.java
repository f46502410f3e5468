package io.rtaware.sim.world;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.map.BeamCaster;
import java.util.random.RandomGenerator;

/**
 * Produces laser scans by ray casting, writing into a caller's preallocated {@link LaserScan}
 * without allocating. Beam directions are precomputed; a scan costs two trigonometric calls
 * plus one ray cast per beam. Not thread-safe (uses the caller's random generator).
 */
public final class Laser {

    private final LaserConfig config;
    private final BeamCaster caster;
    private final double[] cosBearing;
    private final double[] sinBearing;

    /**
     * @param config the laser's parameters
     * @param caster casts each beam (the world map's ray caster, with moving actors if any)
     */
    public Laser(LaserConfig config, BeamCaster caster) {
        this.config = config;
        this.caster = caster;
        this.cosBearing = new double[config.beams()];
        this.sinBearing = new double[config.beams()];
        for (int i = 0; i < config.beams(); i++) {
            double bearing = config.minAngleRad() + i * config.angleIncrementRad();
            cosBearing[i] = StrictMath.cos(bearing);
            sinBearing[i] = StrictMath.sin(bearing);
        }
    }

    /** @return the laser's parameters */
    public LaserConfig config() {
        return config;
    }

    /**
     * Scans from a pose.
     *
     * @param xM sensor x in metres
     * @param yM sensor y in metres
     * @param yawRad sensor heading in radians
     * @param timeS timestamp to put in the scan, seconds
     * @param noise source of range noise (not used when the noise sigma is 0)
     * @param out the scan to fill; its capacity must be at least the beam count
     */
    public void scan(double xM, double yM, double yawRad, double timeS, RandomGenerator noise, LaserScan out) {
        int n = config.beams();
        measure(0, n, xM, yM, yawRad, noise, out);
        finish(timeS, out);
    }

    /**
     * Measures beams {@code from} (inclusive) to {@code to} (exclusive) from one pose, leaving
     * the other beams and the scan's header as they are: a sweeping scanner measures its
     * beams one after another while the robot moves. Finish the scan with
     * {@link #finish(double, LaserScan)}.
     *
     * @param from first beam
     * @param to one past the last beam, at most the beam count
     * @param xM sensor x in metres
     * @param yM sensor y in metres
     * @param yawRad sensor heading in radians
     * @param noise source of range noise (not used when the noise sigma is 0)
     * @param out the scan to fill; its capacity must be at least the beam count
     */
    public void measure(int from, int to, double xM, double yM, double yawRad, RandomGenerator noise,
                        LaserScan out) {
        double c = StrictMath.cos(yawRad);
        double s = StrictMath.sin(yawRad);
        double maxRange = config.maxRangeM();
        double minRange = config.minRangeM();
        double sigma = config.noiseSigmaM();
        float[] ranges = out.rangesM;
        for (int i = from; i < to; i++) {
            double dx = c * cosBearing[i] - s * sinBearing[i];
            double dy = s * cosBearing[i] + c * sinBearing[i];
            double r = caster.castM(xM, yM, dx, dy, maxRange);
            if (r < maxRange) {
                if (sigma > 0) {
                    r += sigma * noise.nextGaussian();
                }
                r = Math.min(maxRange, Math.max(minRange, r));
            }
            ranges[i] = (float) r;
        }
    }

    /**
     * Completes a scan's header: beam count, angles, minimum and maximum range and timestamp.
     *
     * @param timeS timestamp to put in the scan, seconds
     * @param out the scan
     */
    public void finish(double timeS, LaserScan out) {
        int n = config.beams();
        double maxRange = config.maxRangeM();
        out.setCount(n);
        out.minAngleRad = config.minAngleRad();
        out.maxAngleRad = config.maxAngleRad();
        out.maxRangeM = maxRange;
        out.minRangeM = config.minRangeM();
        out.impliedBeams = 0;
        out.serverTimeS = timeS;
    }
}
