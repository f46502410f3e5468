package io.rtaware.core.conditions;

import com.sun.management.GarbageCollectionNotificationInfo;
import java.io.IOException;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.RuntimeMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
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
import jdk.jfr.Recording;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordingFile;

/**
 * The running JVM, through its management beans and JFR: vendor, version, options, collectors
 * and heap from the beans; collection pauses and the time to safepoint from a JFR recording read
 * when the watch closes ({@code jdk.GarbageCollection}, whose {@code sumOfPauses} and
 * {@code longestPause} are in nanoseconds, so ZGC's sub-millisecond pauses are measured, not
 * rounded down to 0 ms as the collector beans' whole milliseconds would; {@code jdk.SafepointBegin},
 * whose duration is the time the threads took to stop). The recording is not streamed: a JFR
 * event stream flushes and parses every second, and beside 10 000 pooled tasks at 10 ms it cost
 * the pool (misses 0.74-1.49 % against 0.00-0.13 % with no recording, median task p99 lateness
 * 4.9-6.5 ms against 3.3-3.5 ms); read at the close, the recording costs less but is not free
 * (0.56-1.76 %, 2.8-3.9 ms). Three interleaved runs each, the 2-vCPU VM, quiet, 2026-11-28.
 * While the run goes, pauses come from the collectors' notifications (a collector bean whose name
 * says {@code Cycles} or {@code Concurrent} counts concurrent work, not pauses, and is left out)
 * and the time to safepoint is not yet known; at the close JFR's figures replace them. On the
 * Epsilon heap, where nothing is ever collected and JFR's own allocations would fill it, or where
 * JFR cannot start, the notifications are all there is and the time to safepoint is not measured.
 */
public final class PlatformJvmProbe implements JvmProbe {

    private static final String SAFEPOINT_EVENT = "jdk.SafepointBegin";
    private static final String GC_EVENT = "jdk.GarbageCollection";
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

    /** Records JFR's collection and safepoint events where it can, and listens to the collectors meanwhile. */
    private static final class PlatformPauseWatch implements PauseWatch, NotificationListener {
        private final AtomicLong count = new AtomicLong();
        private final DoubleAdder totalMs = new DoubleAdder();
        private volatile double maxMs;
        private volatile double maxSafepointMs;
        private final List<NotificationEmitter> emitters = new ArrayList<>();
        private final Recording recording;
        private final StallWatch stalls = StallWatch.start();
        private final String safepointNote;
        /** Why the recording gave no figures, or null. */
        private String unreadable;
        private boolean closed;
        /** Every stop, ms, in the order seen (a handful a minute); past {@link #STOPS_KEPT} only counted. */
        private double[] stopsMs = new double[64];
        private int stopsKept;
        private long stopsNotKept;
        private long safepointCount;
        /** Whether the figures are JFR's (read at the close), not the collectors' notifications. */
        private boolean fromRecording;

        PlatformPauseWatch(boolean epsilon) {
            Recording started = null;
            String note = null;
            if (epsilon) {
                note = "not measured on the Epsilon heap (JFR's own allocations would fill it)";
            } else {
                try {
                    started = new Recording();
                    started.enable(SAFEPOINT_EVENT).withThreshold(Duration.ZERO);
                    started.enable(GC_EVENT).withThreshold(Duration.ZERO);
                    started.setToDisk(true);
                    started.start();
                } catch (RuntimeException | Error e) {
                    if (started != null) {
                        started.close();
                    }
                    started = null;
                    note = "not measured (JFR could not be started: " + e.getMessage() + ")";
                }
            }
            recording = started;
            safepointNote = note;
            for (GarbageCollectorMXBean bean : ManagementFactory.getGarbageCollectorMXBeans()) {
                if (bean instanceof NotificationEmitter emitter && countsPauses(bean.getName())) {
                    emitter.addNotificationListener(this, null, null);
                    emitters.add(emitter);
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

        /**
         * Stops the recording and takes its figures in place of the notifications' (called
         * holding the lock). A recording that cannot be read leaves the notifications' figures
         * and no time to safepoint.
         */
        private void readRecording() {
            Path file = null;
            try {
                recording.stop();
                file = Files.createTempFile("rtaware-pauses-", ".jfr");
                recording.dump(file);
                count.set(0);
                totalMs.reset();
                maxMs = 0;
                stopsKept = 0;
                stopsNotKept = 0;
                try (RecordingFile events = new RecordingFile(file)) {
                    while (events.hasMoreEvents()) {
                        RecordedEvent e = events.readEvent();
                        String type = e.getEventType().getName();
                        if (SAFEPOINT_EVENT.equals(type)) {
                            safepoint(e.getDuration().toNanos() / 1e6);
                        } else if (GC_EVENT.equals(type)) {
                            collected(e.getDuration("sumOfPauses").toNanos() / 1e6,
                                    e.getDuration("longestPause").toNanos() / 1e6);
                        }
                    }
                }
                fromRecording = true;
            } catch (IOException | RuntimeException e) {
                unreadable = "not measured (the JFR recording could not be read: " + e.getMessage() + ")";
            } finally {
                recording.close();
                if (file != null) {
                    try {
                        Files.deleteIfExists(file);
                    } catch (IOException ignored) {
                        // a temporary file left behind: nothing of the run depends on it
                    }
                }
            }
        }

        private void safepoint(double ms) {
            safepointCount++;
            stopped(ms);
            if (ms > maxSafepointMs) {
                maxSafepointMs = ms;
            }
        }

        @Override
        public synchronized void handleNotification(Notification notification, Object handback) {
            if (fromRecording || !GarbageCollectionNotificationInfo.GARBAGE_COLLECTION_NOTIFICATION.equals(notification.getType())) {
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
            return fromRecording ? safepointCount : -1;
        }

        @Override
        public synchronized Double maxTimeToSafepointMs() {
            return fromRecording ? maxSafepointMs : null;
        }

        @Override
        public synchronized String safepointNote() {
            if (safepointNote != null || unreadable != null) {
                return safepointNote != null ? safepointNote : unreadable;
            }
            return fromRecording ? null : "measured when the run ends (JFR, read at the close)";
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
            if (recording != null) {
                readRecording();
            }
        }
    }
}
