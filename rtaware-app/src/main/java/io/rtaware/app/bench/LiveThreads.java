package io.rtaware.app.bench;

import java.util.Arrays;

/**
 * Live threads found with {@link Thread#enumerate}, without the safepoint and stack walk of
 * every thread that {@link Thread#getAllStackTraces()} costs: taken while tasks run, such a walk
 * delayed a pooled run of 10 000 tasks by up to half a second (issue 16).
 */
public final class LiveThreads {

    private LiveThreads() {
    }

    /** @return the live threads of this JVM's thread groups, now */
    public static Thread[] all() {
        Thread[] all = new Thread[Thread.activeCount() + 64];
        int n;
        while ((n = Thread.enumerate(all)) == all.length) {
            all = new Thread[all.length * 2];
        }
        return Arrays.copyOf(all, n);
    }

    /**
     * @param prefix the start of the wanted threads' names
     * @return the ids of the live threads whose names start with {@code prefix}
     */
    public static long[] idsNamed(String prefix) {
        return Arrays.stream(all()).filter(t -> t.getName().startsWith(prefix)).mapToLong(Thread::getId).toArray();
    }
}
