package io.rtaware.core.conditions;

import com.sun.management.GarbageCollectionNotificationInfo;
import java.io.IOException;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.RuntimeMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
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

/**
 * The running JVM, through its management beans and its own safepoint log: vendor, version,
 * options, collectors and heap from the beans; the safepoints, the time to reach each, and the
 * collectors' pauses from the JVM's unified logging ({@link SafepointLog}), switched on when the
 * watch starts and read when it closes, in nanoseconds (so ZGC's sub-millisecond pauses are
 * measured, not rounded down to 0 ms as the collector beans' whole milliseconds would).
 *
 * <p>Why a log and not JFR: a JFR event stream flushes and parses every second, and beside 10 000
 * pooled tasks at 10 ms it cost the pool (misses 0.74-1.49 % against 0.00-0.13 % with no
 * recording, median task p99 lateness 4.9-6.5 ms against 3.3-3.5 ms); a recording read at the
 * close cost less but was not free (0.56-1.76 %, 2.8-3.9 ms; three interleaved runs each, the
 * 2-vCPU VM, quiet, 2026-11-28). The log is written by the VM thread as each safepoint ends, a
 * line at a time, and nothing else runs.
 *
 * <p>While the run goes, pauses come from the collectors' notifications (a collector bean whose
 * name says {@code Cycles} or {@code Concurrent} counts concurrent work, not pauses, and is left
 * out) and the time to safepoint is not yet known; at the close the log's figures replace them.
 * Where the log cannot be switched on (a JVM without HotSpot's diagnostic commands), the
 * notifications are all there is and the time to safepoint is not measured.
 */
public final class PlatformJvmProbe implements JvmProbe {

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
        return new PlatformPauseWatch();
    }

    /**
     * @param collectorName a collector bean's name
     * @return true if its notifications are pauses (not concurrent cycles)
     */
    static boolean countsPauses(String collectorName) {
        String n = collectorName.toLowerCase(Locale.ROOT);
        return !n.contains("cycles") && !n.contains("concurrent");
    }

    /** Logs the safepoints where it can, and listens to the collectors meanwhile. */
    private static final class PlatformPauseWatch implements PauseWatch, NotificationListener {
        private final AtomicLong count = new AtomicLong();
        private final DoubleAdder totalMs = new DoubleAdder();
        private volatile double maxMs;
        private volatile double maxSafepointMs;
        private final List<NotificationEmitter> emitters = new ArrayList<>();
        /** The safepoint log and its file; null where it could not be switched on. */
        private final SafepointLog log;
        private final Path logFile;
        private final StallWatch stalls = StallWatch.start();
        private final String safepointNote;
        /** Why the log gave no figures, or null. */
        private String unreadable;
        private boolean closed;
        /** Every stop, ms, in the order seen (a handful a minute); past {@link #STOPS_KEPT} only counted. */
        private double[] stopsMs = new double[64];
        private int stopsKept;
        private long stopsNotKept;
        private long safepointCount;
        /** Whether the figures are the log's (read at the close), not the collectors' notifications. */
        private boolean fromLog;

        PlatformPauseWatch() {
            SafepointLog started = null;
            Path file = null;
            String note = null;
            try {
                file = Files.createTempFile("rtaware-safepoints-", ".log");
                started = SafepointLog.start(file);
            } catch (IOException e) {
                deleteQuietly(file);
                file = null;
                note = "not measured (the JVM's safepoint log could not be switched on: " + e.getMessage() + ")";
            }
            log = started;
            logFile = file;
            safepointNote = note;
            for (GarbageCollectorMXBean bean : ManagementFactory.getGarbageCollectorMXBeans()) {
                if (bean instanceof NotificationEmitter emitter && countsPauses(bean.getName())) {
                    emitter.addNotificationListener(this, null, null);
                    emitters.add(emitter);
                }
            }
        }

        /** One collection (a notification) or one collector pause (the log): its pauses summed and its longest, ms. */
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
         * Stops the log and takes its figures in place of the notifications' (called holding the
         * lock): every safepoint counts with its time to reach, and a collector's pause with its
         * time at the safepoint. A log that cannot be read leaves the notifications' figures and
         * no time to safepoint.
         */
        private void readLog() {
            try {
                List<SafepointLog.Safepoint> safepoints = log.stop();
                count.set(0);
                totalMs.reset();
                maxMs = 0;
                stopsKept = 0;
                stopsNotKept = 0;
                for (SafepointLog.Safepoint s : safepoints) {
                    safepoint(s.reachingNs() / 1e6);
                    if (s.collectorPause()) {
                        double pauseMs = s.atSafepointNs() / 1e6;
                        collected(pauseMs, pauseMs);
                    }
                }
                fromLog = true;
            } catch (IOException e) {
                unreadable = "not measured (the JVM's safepoint log could not be read: " + e.getMessage() + ")";
            } finally {
                deleteQuietly(logFile);
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
            if (fromLog || !GarbageCollectionNotificationInfo.GARBAGE_COLLECTION_NOTIFICATION.equals(notification.getType())) {
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
            return fromLog ? safepointCount : -1;
        }

        @Override
        public synchronized Double maxTimeToSafepointMs() {
            return fromLog ? maxSafepointMs : null;
        }

        @Override
        public synchronized String safepointNote() {
            if (safepointNote != null || unreadable != null) {
                return safepointNote != null ? safepointNote : unreadable;
            }
            return fromLog ? null : "measured when the run ends (the JVM's safepoint log, read at the close)";
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
            if (log != null) {
                readLog();
            }
        }
    }

    /** Deletes a temporary file of the watch, if there is one; one left behind harms nothing of the run. */
    private static void deleteQuietly(Path file) {
        if (file == null) {
            return;
        }
        try {
            Files.deleteIfExists(file);
        } catch (IOException ignored) {
            // a temporary file left behind: nothing of the run depends on it
        }
    }
}
