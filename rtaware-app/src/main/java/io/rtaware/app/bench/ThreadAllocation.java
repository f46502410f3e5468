package io.rtaware.app.bench;

import io.rtaware.live.LiveView;
import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.Comparator;
import java.util.Set;

/**
 * Bytes allocated by a fixed set of live threads, read from
 * {@code com.sun.management.ThreadMXBean#getThreadAllocatedBytes}: take a snapshot at the start
 * of the steady state and ask it, at the end, how much those threads allocated since. Immutable.
 */
public final class ThreadAllocation {

    /**
     * Threads of the monitor that are not on the per-release path (they print, stop, write a
     * recording from what the task threads handed over, or build the live view's snapshots).
     */
    private static final Set<String> OFF_PATH = Set.of("rtaware-console", "rtaware-shutdown", "rtaware-stop",
            "rtaware-recorder", LiveView.PUBLISHER_THREAD);

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
     * at the start of the steady state, a third into the run.
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
     * Snapshots the monitor's threads on the per-release path: every live thread named
     * {@code rtaware-*} (the task threads, the pool workers {@code rtaware-pool-N} and the watchdog
     * {@code rtaware-monitor}) except the
     * console printer, the stop helpers, the recorder's writer and the live view's publisher.
     *
     * @return the snapshot
     */
    public static ThreadAllocation ofFrameworkThreads() {
        com.sun.management.ThreadMXBean bean = bean();
        Thread[] watched = Arrays.stream(LiveThreads.all())
                .filter(t -> t.getName().startsWith("rtaware-") && !OFF_PATH.contains(t.getName()))
                .sorted(Comparator.comparingLong(Thread::getId)).toArray(Thread[]::new);
        return new ThreadAllocation(bean, Arrays.stream(watched).mapToLong(Thread::getId).toArray(),
                Arrays.stream(watched).map(Thread::getName).toArray(String[]::new));
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
        long[] now = bean.getThreadAllocatedBytes(ids);
        long[] since = new long[ids.length];
        for (int i = 0; i < ids.length; i++) {
            since[i] = bytes[i] >= 0 && now[i] >= 0 ? now[i] - bytes[i] : 0;
        }
        return since;
    }

    /**
     * Which watched threads allocated since the snapshot, for the line that reports an
     * allocation: a task thread points at the task's cycle, the watchdog at the monitor's scan.
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
