package io.rtaware.bench.load;

import io.rtaware.core.monitor.MonitorListener;
import io.rtaware.core.monitor.TaskInfo;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.HdrHistogram.ConcurrentHistogram;
import org.HdrHistogram.HistogramIterationValue;

/**
 * {@code bench --lateness-histogram FILE}: every cycle's release lateness (start minus release,
 * as the monitor reports it), of every task, in 1 us buckets, written in cyclictest's histogram
 * format ({@code <us> <count>} per line), so the two can be merged and compared by the same
 * script ({@code scripts/compare-cyclictest.sh}). Recording is allocation-free and safe from
 * every task thread at once.
 */
public final class LatenessHistogram implements MonitorListener {

    private static final long HIGHEST_TRACKABLE_NS = 60_000_000_000L;
    private static final long BUCKET_NS = 1_000;

    private final ConcurrentHistogram latenessNs = new ConcurrentHistogram(1, HIGHEST_TRACKABLE_NS, 3);

    /** An empty histogram; add it to a monitor as a listener. */
    public LatenessHistogram() {
    }

    @Override
    public void onCycle(TaskInfo task, long releaseNs, long startNs, long endNs) {
        latenessNs.recordValue(Math.min(Math.max(0, startNs - releaseNs), HIGHEST_TRACKABLE_NS));
    }

    /**
     * @param file where to write the {@code <us> <count>} lines (buckets with samples only)
     * @throws IOException if it cannot be written
     */
    public void write(Path file) throws IOException {
        try (PrintWriter out = new PrintWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8))) {
            out.println("# rtaware release lateness, 1 us buckets: <us> <count>");
            for (HistogramIterationValue v : latenessNs.linearBucketValues(BUCKET_NS)) {
                if (v.getCountAddedInThisIterationStep() > 0) {
                    out.println((v.getValueIteratedTo() / BUCKET_NS) + " " + v.getCountAddedInThisIterationStep());
                }
            }
        }
    }
}
