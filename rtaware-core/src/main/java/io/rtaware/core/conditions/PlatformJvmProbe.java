package io.rtaware.core.conditions;

import com.sun.management.GarbageCollectionNotificationInfo;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.RuntimeMXBean;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.DoubleAdder;
import javax.management.ListenerNotFoundException;
import javax.management.Notification;
import javax.management.NotificationEmitter;
import javax.management.NotificationListener;
import javax.management.openmbean.CompositeData;
import jdk.jfr.consumer.RecordingStream;

/**
 * The running JVM, through its management beans and JFR: vendor, version, options, collectors
 * and heap from the beans; collection pauses and the time to safepoint from JFR event streaming
 * ({@code jdk.GarbageCollection}, whose {@code sumOfPauses} and {@code longestPause} are in
 * nanoseconds, so ZGC's sub-millisecond pauses are measured, not rounded down to 0 ms as the
 * collector beans' whole milliseconds would; {@code jdk.SafepointBegin}, whose duration is the
 * time the threads took to stop). On the Epsilon heap, where nothing is ever collected and JFR's
 * own allocations would fill it, or where JFR cannot start, pauses come from the collectors'
 * notifications instead (a collector bean whose name says {@code Cycles} or {@code Concurrent}
 * counts concurrent work, not pauses, and is left out) and the time to safepoint is not
 * measured. JFR delivers events about once a second, so closing waits (at most 2.5 s) for the
 * buffered ones.
 */
public final class PlatformJvmProbe implements JvmProbe {

    private static final String SAFEPOINT_EVENT = "jdk.SafepointBegin";
    private static final String GC_EVENT = "jdk.GarbageCollection";
    /** The longest wait at the end for JFR to deliver the events still buffered (it flushes about once a second). */
    private static final long FLUSH_WAIT_MS = 2500;
    /** Stops kept for {@link PauseWatch#stopsLongerThan}; any beyond count as longer than every limit. */
    private static final int STOPS_KEPT = 1 << 16;

    @Override
    public String vendor() {
        return System.getProperty("java.vm.vendor", "unknown");
    }

    @Override
    public String version() {
        return System.getProperty("java.vm.version", System.getProperty("java.version", "unknown"));
    }

    @Override
    public List<String> options() {
        RuntimeMXBean runtime = ManagementFactory.getRuntimeMXBean();
        return List.copyOf(runtime.getInputArguments());
    }

    @Override
    public List<String> collectors() {
        return ManagementFactory.getGarbageCollectorMXBeans().stream().map(GarbageCollectorMXBean::getName).toList();
    }

    @Override
    public long heapMaxBytes() {
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getMax();
    }

    @Override
    public PauseWatch watchPauses() {
        return new PlatformPauseWatch(options().stream().anyMatch(o -> o.contains("UseEpsilonGC")));
    }

    /**
     * @param collectorName a collector bean's name
     * @return true if its notifications are pauses (not concurrent cycles)
     */
    static boolean countsPauses(String collectorName) {
        String n = collectorName.toLowerCase(Locale.ROOT);
        return !n.contains("cycles") && !n.contains("concurrent");
    }

    /** Streams JFR's collection and safepoint events where it can, else listens to the collectors. */
    private static final class PlatformPauseWatch implements PauseWatch, NotificationListener {
        private final AtomicLong count = new AtomicLong();
        private final DoubleAdder totalMs = new DoubleAdder();
        private volatile double maxMs;
        private volatile double maxSafepointMs;
        private final List<NotificationEmitter> emitters = new ArrayList<>();
        private final RecordingStream stream;
        private final StallWatch stalls = StallWatch.start();
        private final String safepointNote;
        private boolean closed;
        /** Every stop, ms, in the order seen (a handful a minute); past {@link #STOPS_KEPT} only counted. */
        private double[] stopsMs = new double[64];
        private int stopsKept;
        private long stopsNotKept;
        private long flushes;
        private long safepointCount;

        PlatformPauseWatch(boolean epsilon) {
            RecordingStream started = null;
            String note = null;
            if (epsilon) {
                note = "not measured on the Epsilon heap (JFR's own allocations would fill it)";
            } else {
                try {
                    started = new RecordingStream();
                    started.enable(SAFEPOINT_EVENT).withThreshold(Duration.ZERO);
                    started.onEvent(SAFEPOINT_EVENT, e -> safepoint(e.getDuration().toNanos() / 1e6));
                    started.enable(GC_EVENT).withThreshold(Duration.ZERO);
                    started.onEvent(GC_EVENT, e -> collected(e.getDuration("sumOfPauses").toNanos() / 1e6,
                            e.getDuration("longestPause").toNanos() / 1e6));
                    started.onFlush(this::flushed);
                    started.startAsync();
                } catch (RuntimeException | Error e) {
                    if (started != null) {
                        started.close();
                    }
                    started = null;
                    note = "not measured (JFR could not be started: " + e.getMessage() + ")";
                }
            }
            stream = started;
            safepointNote = note;
            if (stream == null) {
                for (GarbageCollectorMXBean bean : ManagementFactory.getGarbageCollectorMXBeans()) {
                    if (bean instanceof NotificationEmitter emitter && countsPauses(bean.getName())) {
                        emitter.addNotificationListener(this, null, null);
                        emitters.add(emitter);
                    }
                }
            }
        }

        /** One collection: its pauses summed and its longest, ms. */
        private void collected(double pausesMs, double longestMs) {
            count.incrementAndGet();
            totalMs.add(pausesMs);
            synchronized (this) {
                if (longestMs > maxMs) {
                    maxMs = longestMs;
                }
                stopped(longestMs);
            }
        }

        /** Keeps one stop's length; called holding the lock. */
        private void stopped(double ms) {
            if (stopsKept == STOPS_KEPT) {
                stopsNotKept++;
                return;
            }
            if (stopsKept == stopsMs.length) {
                stopsMs = Arrays.copyOf(stopsMs, Math.min(STOPS_KEPT, stopsMs.length * 2));
            }
            stopsMs[stopsKept++] = ms;
        }

        @Override
        public synchronized long stopsLongerThan(double ms) {
            long n = stopsNotKept;
            for (int i = 0; i < stopsKept; i++) {
                if (stopsMs[i] > ms) {
                    n++;
                }
            }
            return n;
        }

        /** Counts the stream's flushes: each delivered every event recorded before it. */
        private synchronized void flushed() {
            flushes++;
            notifyAll();
        }

        /** Waits (at most {@link #FLUSH_WAIT_MS}) for two more flushes, so the last second's events are in. */
        private synchronized void awaitFlushes() {
            long target = flushes + 2;
            long deadline = System.nanoTime() + FLUSH_WAIT_MS * 1_000_000L;
            try {
                while (flushes < target && System.nanoTime() < deadline) {
                    wait(Math.max(1, (deadline - System.nanoTime()) / 1_000_000L));
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        private synchronized void safepoint(double ms) {
            safepointCount++;
            stopped(ms);
            if (ms > maxSafepointMs) {
                maxSafepointMs = ms;
            }
        }

        @Override
        public void handleNotification(Notification notification, Object handback) {
            if (!GarbageCollectionNotificationInfo.GARBAGE_COLLECTION_NOTIFICATION.equals(notification.getType())) {
                return;
            }
            GarbageCollectionNotificationInfo info =
                    GarbageCollectionNotificationInfo.from((CompositeData) notification.getUserData());
            double ms = info.getGcInfo().getDuration(); // whole milliseconds: the beans say no more
            collected(ms, ms);
        }

        @Override
        public long gcCount() {
            return count.get();
        }

        @Override
        public double gcTotalMs() {
            return totalMs.sum();
        }

        @Override
        public double gcMaxPauseMs() {
            return maxMs;
        }

        @Override
        public synchronized long safepoints() {
            return stream == null ? -1 : safepointCount;
        }

        @Override
        public Double maxTimeToSafepointMs() {
            return stream == null ? null : maxSafepointMs;
        }

        @Override
        public String safepointNote() {
            return safepointNote;
        }

        @Override
        public double longestStallMs() {
            return stalls.longestStallMs();
        }

        @Override
        public synchronized void close() {
            if (closed) {
                return;
            }
            closed = true;
            stalls.close();
            for (NotificationEmitter emitter : emitters) {
                try {
                    emitter.removeNotificationListener(this);
                } catch (ListenerNotFoundException ignored) {
                    // never added: nothing to remove
                }
            }
            if (stream != null) {
                awaitFlushes();
                stream.close();
            }
        }
    }
}
