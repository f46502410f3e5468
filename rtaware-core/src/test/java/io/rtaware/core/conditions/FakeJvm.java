package io.rtaware.core.conditions;

import java.util.List;

/** A JVM that says what a test tells it: fixed identity, and the pauses a test sets. */
final class FakeJvm implements JvmProbe {

    long gcCount;
    double gcTotalMs;
    double gcMaxPauseMs;
    Double safepointMaxMs;
    double[] stopsMs = {};
    double longestStallMs;
    boolean closed;

    @Override
    public String vendor() {
        return "Test Vendor";
    }

    @Override
    public String version() {
        return "17.0.99";
    }

    @Override
    public List<String> options() {
        return List.of("-XX:+UseZGC", "-Xmx512m");
    }

    @Override
    public List<String> collectors() {
        return List.of("ZGC Cycles", "ZGC Pauses");
    }

    @Override
    public long heapMaxBytes() {
        return 512L << 20;
    }

    @Override
    public PauseWatch watchPauses() {
        return new PauseWatch() {
            @Override
            public long gcCount() {
                return gcCount;
            }

            @Override
            public double gcTotalMs() {
                return gcTotalMs;
            }

            @Override
            public double gcMaxPauseMs() {
                return gcMaxPauseMs;
            }

            @Override
            public long stopsLongerThan(double ms) {
                return java.util.Arrays.stream(stopsMs).filter(s -> s > ms).count();
            }

            @Override
            public long safepoints() {
                return safepointMaxMs == null ? -1 : 1;
            }

            @Override
            public Double maxTimeToSafepointMs() {
                return safepointMaxMs;
            }

            @Override
            public String safepointNote() {
                return safepointMaxMs == null ? "not measured in this test" : null;
            }

            @Override
            public double longestStallMs() {
                return longestStallMs;
            }

            @Override
            public void close() {
                closed = true;
            }
        };
    }
}
