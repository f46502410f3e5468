package io.rtaware.app.cli;

import io.rtaware.app.UserError;
import java.util.Locale;

/**
 * The heap a command may still use, so that a configuration that cannot fit ({@code bench
 * --tasks 100000}, {@code --trace-capacity 2000000000}, a 20000 x 20000 map) is refused with the
 * numbers before anything is allocated, instead of ending in an OutOfMemoryError. The budget is a
 * fixed share ({@value #USABLE_PERCENT} %) of what the JVM's maximum heap leaves after what is
 * already in use; the rest is headroom for the run's own garbage.
 */
public final class MemoryBudget {

    /** Share of the free heap a configuration may claim up front. */
    static final int USABLE_PERCENT = 80;
    private static final long MB = 1024 * 1024;

    private final long maxHeapBytes;
    private final long usedBytes;

    /**
     * @param maxHeapBytes the JVM's maximum heap ({@code -Xmx})
     * @param usedBytes heap already in use
     */
    public MemoryBudget(long maxHeapBytes, long usedBytes) {
        if (maxHeapBytes <= 0 || usedBytes < 0) {
            throw new IllegalArgumentException("heap sizes must be positive, got max " + maxHeapBytes + ", used " + usedBytes);
        }
        this.maxHeapBytes = maxHeapBytes;
        this.usedBytes = usedBytes;
    }

    /** @return the budget of this JVM now */
    public static MemoryBudget ofThisJvm() {
        Runtime rt = Runtime.getRuntime();
        return new MemoryBudget(rt.maxMemory(), rt.totalMemory() - rt.freeMemory());
    }

    /** @return bytes a configuration may claim */
    public long availableBytes() {
        return Math.max(0, (maxHeapBytes - usedBytes) / 100 * USABLE_PERCENT);
    }

    /**
     * @param neededBytes the estimate of what the configuration allocates
     * @param what the configuration in the user's words, e.g. {@code --tasks 100000 (75 KB per task)}
     * @throws UserError naming the configuration, the estimate, the budget and how to raise it
     */
    public void require(long neededBytes, String what) {
        if (neededBytes > availableBytes()) {
            throw new UserError(String.format(Locale.ROOT,
                    "%s needs about %s of heap, but only %s of this JVM's %s maximum is available; "
                            + "ask for less, or raise the heap (RTAWARE_JAVA_OPTS=\"-Xmx4g ...\", see "
                            + "docs/troubleshooting.md)",
                    what, size(neededBytes), size(availableBytes()), size(maxHeapBytes)));
        }
    }

    /**
     * @param a a byte count
     * @param b another
     * @return their sum, saturated at {@link Long#MAX_VALUE}
     */
    public static long add(long a, long b) {
        long sum = a + b;
        return ((a ^ sum) & (b ^ sum)) < 0 ? Long.MAX_VALUE : sum;
    }

    /**
     * @param count how many
     * @param bytesEach bytes of one
     * @return the product, saturated at {@link Long#MAX_VALUE}
     */
    public static long times(long count, long bytesEach) {
        return count != 0 && bytesEach > Long.MAX_VALUE / count ? Long.MAX_VALUE : count * bytesEach;
    }

    /**
     * @param bytes a size
     * @return it in MB (or GB, TB) for a person
     */
    public static String size(long bytes) {
        if (bytes >= 1024L * 1024 * MB) {
            return String.format(Locale.ROOT, "%.1f TB", bytes / (1024.0 * 1024 * MB));
        }
        if (bytes >= 1024 * MB) {
            return String.format(Locale.ROOT, "%.1f GB", bytes / (1024.0 * MB));
        }
        return String.format(Locale.ROOT, "%d MB", (bytes + MB - 1) / MB);
    }
}
