package io.rtaware.ros2msg.value;

/**
 * One {@code statistics_msgs/msg/MetricsMessage}: the statistics of one metric of one source over
 * one window of time, as ROS 2's topic statistics publish them on {@code /statistics}. Mutable;
 * text lives in {@link StringBuilder}s that are reused, the data points in arrays of a fixed
 * capacity. Not thread-safe.
 */
public final class MetricsMessage {

    /** {@code StatisticDataType.STATISTICS_DATA_TYPE_UNINITIALIZED}. */
    public static final byte UNINITIALIZED = 0;
    /** {@code StatisticDataType.STATISTICS_DATA_TYPE_AVERAGE}. */
    public static final byte AVERAGE = 1;
    /** {@code StatisticDataType.STATISTICS_DATA_TYPE_MINIMUM}. */
    public static final byte MINIMUM = 2;
    /** {@code StatisticDataType.STATISTICS_DATA_TYPE_MAXIMUM}. */
    public static final byte MAXIMUM = 3;
    /** {@code StatisticDataType.STATISTICS_DATA_TYPE_STDDEV}. */
    public static final byte STDDEV = 4;
    /** {@code StatisticDataType.STATISTICS_DATA_TYPE_SAMPLE_COUNT}. */
    public static final byte SAMPLE_COUNT = 5;

    /** what was measured: a node, a topic; in rtaware a task or a key. */
    public final StringBuilder measurementSourceName = new StringBuilder(32);
    /** the metric, e.g. {@code message_age}. */
    public final StringBuilder metricsSource = new StringBuilder(32);
    /** its unit, e.g. {@code ms}. */
    public final StringBuilder unit = new StringBuilder(8);
    /** the window's start, ns since the epoch of the stamps. */
    public long windowStartNs;
    /** the window's end, ns since the epoch of the stamps. */
    public long windowStopNs;
    private final byte[] dataTypes;
    private final double[] data;
    private int count;

    /** @param capacityPoints the most data points the message holds */
    public MetricsMessage(int capacityPoints) {
        dataTypes = new byte[capacityPoints];
        data = new double[capacityPoints];
    }

    /** Empties the message: no text, window 0 to 0, no data points. */
    public void clear() {
        measurementSourceName.setLength(0);
        metricsSource.setLength(0);
        unit.setLength(0);
        windowStartNs = 0;
        windowStopNs = 0;
        count = 0;
    }

    /**
     * Appends a data point.
     *
     * @param dataType one of {@link #AVERAGE}, {@link #MINIMUM}, {@link #MAXIMUM}, {@link #STDDEV},
     *     {@link #SAMPLE_COUNT} (any byte on decoding)
     * @param value its value
     * @throws IllegalStateException if the message is full
     */
    public void add(byte dataType, double value) {
        if (count == dataTypes.length) {
            throw new IllegalStateException("MetricsMessage full: " + count + " data points");
        }
        dataTypes[count] = dataType;
        data[count] = value;
        count++;
    }

    /** @return the number of data points */
    public int count() {
        return count;
    }

    /** @return the most data points the message holds */
    public int capacity() {
        return dataTypes.length;
    }

    /**
     * @param i a data point's index, below {@link #count()}
     * @return its data type
     */
    public byte dataType(int i) {
        check(i);
        return dataTypes[i];
    }

    /**
     * @param i a data point's index, below {@link #count()}
     * @return its value
     */
    public double data(int i) {
        check(i);
        return data[i];
    }

    /**
     * @param dataType a data type
     * @return the value of the first data point of that type, or NaN if there is none
     */
    public double valueOf(byte dataType) {
        for (int i = 0; i < count; i++) {
            if (dataTypes[i] == dataType) {
                return data[i];
            }
        }
        return Double.NaN;
    }

    private void check(int i) {
        if (i < 0 || i >= count) {
            throw new IndexOutOfBoundsException("data point " + i + " of " + count);
        }
    }
}
