package io.rtaware.ros2msg.statistics;

import io.rtaware.ros2msg.value.MetricsMessage;

/**
 * One metric's samples over one window, as ROS 2's statistics collectors keep them: count, mean
 * and the sum of squared differences from it (Welford's updates), minimum and maximum. Reset for
 * every window; allocates nothing.
 */
final class Moments {

    private long count;
    private double mean;
    private double squaredDifferences;
    private double min;
    private double max;

    /** Adds a sample. */
    void add(double x) {
        count++;
        double d = x - mean;
        mean += d / count;
        squaredDifferences += d * (x - mean);
        if (count == 1 || x < min) {
            min = x;
        }
        if (count == 1 || x > max) {
            max = x;
        }
    }

    /** @return samples added since the last reset */
    long count() {
        return count;
    }

    /**
     * Appends AVERAGE, MINIMUM, MAXIMUM, STDDEV (the population's, as ROS 2's collectors compute
     * it) and SAMPLE_COUNT, in that order; without samples the first four are NaN and the count 0.
     */
    void writeTo(MetricsMessage m) {
        boolean any = count > 0;
        m.add(MetricsMessage.AVERAGE, any ? mean : Double.NaN);
        m.add(MetricsMessage.MINIMUM, any ? min : Double.NaN);
        m.add(MetricsMessage.MAXIMUM, any ? max : Double.NaN);
        m.add(MetricsMessage.STDDEV, any ? Math.sqrt(squaredDifferences / count) : Double.NaN);
        m.add(MetricsMessage.SAMPLE_COUNT, count);
    }

    /** Forgets every sample. */
    void reset() {
        count = 0;
        mean = 0;
        squaredDifferences = 0;
        min = 0;
        max = 0;
    }
}
