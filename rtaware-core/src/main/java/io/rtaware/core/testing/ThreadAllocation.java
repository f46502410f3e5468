package io.rtaware.core.testing;

import io.rtaware.core.agent.ThreadNames;
import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.Comparator;
import java.util.Set;
import java.util.function.Predicate;

/**
 * Bytes allocated by a fixed set of threads, read from
 * {@code com.sun.management.ThreadMXBean#getThreadAllocatedBytes}: take a snapshot at the start
 * of a steady state and ask it, at the end, how much those threads allocated since. How a test or
 * a benchmark checks that steady-state task cycles allocate nothing ({@code rtaware bench
 * --fail-on-alloc}, the executor comparison's {@code alloc_bytes}). A thread gone by the second
 * read is left out of the sums. Immutable; the reads may come from any thread.
 */
public final class ThreadAllocation {

    /**
     * Threads of the framework that are not on the per-release path (they print, stop, write a
     * recording from what the task threads handed over, or build the live view's snapshots); the
     * live view's HTTP threads, which serve them, are told by {@link ThreadNames#LIVE_HTTP_PREFIX}.
     */
    private static final Set<String> OFF_PATH = Set.of(ThreadNames.CONSOLE, ThreadNames.SHUTDOWN, ThreadNames.STOP,
            ThreadNames.RECORDER, ThreadNames.LIVE_PUBLISHER);

    private final com.sun.management.ThreadMXBean bean;
    private final long[] ids;
    private final String[] names;
    private final long[] bytes;

    private ThreadAllocation(com.sun.management.ThreadMXBean bean, long[] ids, String[] names) {
        this.bean = bean;
        this.ids = ids;
        this.names = names;
        this.bytes = bean.getThreadAllocatedBytes(ids);
    }

    /**
     * Loads and starts the JVM's management beans and turns allocation counting on, before a run
     * starts, so that their first use (class loading) does not compete with the tasks for a core
     * at the start of the steady state.
     */
    public static void prepare() {
        bean();
    }

    private static com.sun.management.ThreadMXBean bean() {
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        if (bean.isThreadAllocatedMemorySupported()) {
            bean.setThreadAllocatedMemoryEnabled(true);
        }
        return bean;
    }

    /**
     * Snapshots the framework's threads on the per-release path: every live thread named
     * {@value ThreadNames#PREFIX}{@code *} that is {@link #onReleasePath on the per-release path}:
     * the task threads, the pool workers {@value ThreadNames#POOL_WORKER_PREFIX}{@code N}, the
     * watchdog {@value ThreadNames#WATCHDOG} and the pool's statistics recorder
     * {@value ThreadNames#STATISTICS}.
     *
     * @return the snapshot
     */
    public static ThreadAllocation ofFrameworkThreads() {
        return ofLiveThreads(ThreadAllocation::onReleasePath);
    }

    /**
     * Whether a thread is one {@link #ofFrameworkThreads()} watches: named {@value ThreadNames#PREFIX}{@code *}
     * and none of the observers off the per-release path ({@link ThreadNames}): the console printer,
     * the stop helpers, the recorder's writer, the live view's publisher and HTTP threads.
     *
     * @param thread a thread
     * @return whether its allocation counts as the framework's on the per-release path
     */
    public static boolean onReleasePath(Thread thread) {
        String name = thread.getName();
        return name.startsWith(ThreadNames.PREFIX) && !OFF_PATH.contains(name)
                && !name.startsWith(ThreadNames.LIVE_HTTP_PREFIX);
    }

    /**
     * Snapshots the live threads that {@code which} accepts, in the order of their ids.
     *
     * @param which the threads to watch
     * @return the snapshot
     */
    public static ThreadAllocation ofLiveThreads(Predicate<Thread> which) {
        Thread[] watched = Arrays.stream(LiveThreads.all()).filter(which)
                .sorted(Comparator.comparingLong(Thread::getId)).toArray(Thread[]::new);
        return new ThreadAllocation(bean(), Arrays.stream(watched).mapToLong(Thread::getId).toArray(),
                Arrays.stream(watched).map(Thread::getName).toArray(String[]::new));
    }

    /**
     * Snapshots threads known by their ids (named {@code thread ID} in {@link #allocatingThreads()}).
     *
     * @param threadIds the threads' ids, each once
     * @return the snapshot
     */
    public static ThreadAllocation ofThreadIds(long... threadIds) {
        long[] ids = threadIds.clone();
        return new ThreadAllocation(bean(), ids,
                Arrays.stream(ids).mapToObj(id -> "thread " + id).toArray(String[]::new));
    }

    /** @return how many threads are watched */
    public int threads() {
        return ids.length;
    }

    /** @return bytes the watched threads allocated since the snapshot (threads gone meanwhile are left out) */
    public long allocatedSince() {
        long sum = 0;
        for (long b : perThreadSince()) {
            sum += b;
        }
        return sum;
    }

    /** @return per watched thread, bytes allocated since the snapshot (0 for a thread gone meanwhile) */
    private long[] perThreadSince() {
        return between(bytes, bean.getThreadAllocatedBytes(ids));
    }

    /**
     * @param before per thread, a first read of its allocated bytes (-1: not known)
     * @param after per thread, a later read (-1: the thread is gone)
     * @return per thread, the bytes allocated in between (0 where either read is -1)
     */
    static long[] between(long[] before, long[] after) {
        long[] since = new long[before.length];
        for (int i = 0; i < before.length; i++) {
            since[i] = before[i] >= 0 && after[i] >= 0 ? after[i] - before[i] : 0;
        }
        return since;
    }

    /**
     * Which watched threads allocated since the snapshot, for the line that reports an
     * allocation: a task thread points at the task's cycle, the watchdog at the monitor's scan.
     * Ask while the threads still live (a thread gone is left out).
     *
     * @return e.g. {@code rtaware-t3 80 B, rtaware-monitor 16 B}, or an empty string when none did
     */
    public String allocatingThreads() {
        long[] since = perThreadSince();
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < ids.length; i++) {
            if (since[i] > 0) {
                out.append(out.length() == 0 ? "" : ", ").append(names[i]).append(' ').append(since[i]).append(" B");
            }
        }
        return out.toString();
    }

    @Override
    public String toString() {
        return "ThreadAllocation" + Arrays.toString(ids);
    }
}
