package io.rtaware.app.bench.compare;

import java.util.Arrays;

/** Live threads by name, without a safepoint or a stack walk. */
final class LiveThreads {

    private LiveThreads() {
    }

    /**
     * @param prefix the start of the wanted threads' names
     * @return the ids of the live threads whose names start with {@code prefix}
     */
    static long[] idsNamed(String prefix) {
        Thread[] all = new Thread[Thread.activeCount() + 64];
        int n;
        while ((n = Thread.enumerate(all)) == all.length) {
            all = new Thread[all.length * 2];
        }
        return Arrays.stream(all, 0, n).filter(t -> t.getName().startsWith(prefix))
                .mapToLong(Thread::getId).toArray();
    }
}
