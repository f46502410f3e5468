package io.rtaware.record.mcap;

/** How chunk records are compressed. */
public enum Compression {
    /** Uncompressed chunks. */
    NONE(""),
    /** Zstandard (the default of ROS 2 bags and Foxglove), through zstd-jni. */
    ZSTD("zstd"),
    /** LZ4 frames (MCAP's other compression), through Apache Commons Compress. */
    LZ4("lz4");

    private final String mcapName;

    Compression(String mcapName) {
        this.mcapName = mcapName;
    }

    /** @return the name in the chunk record's {@code compression} field */
    public String mcapName() {
        return mcapName;
    }
}
