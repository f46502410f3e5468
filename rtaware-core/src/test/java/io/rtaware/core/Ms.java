package io.rtaware.core;

/** Millisecond helpers for tests. */
public final class Ms {
    private Ms() {
    }

    public static long ms(long millis) {
        return millis * 1_000_000L;
    }

    public static long ms(double millis) {
        return Math.round(millis * 1_000_000.0);
    }
}
