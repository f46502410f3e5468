package io.rtaware.core.testing;

import java.util.Arrays;

/**
 * Live threads found with {@link Thread#enumerate}, without the safepoint and stack walk of
 * every thread that {@link Thread#getAllStackTraces()} costs while tasks run (with 1000 task
 * threads: 28 MB and a stall inside a measured window, issue 16's profile). Stateless.
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
