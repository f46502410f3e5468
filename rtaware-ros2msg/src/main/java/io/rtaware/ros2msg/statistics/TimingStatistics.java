package io.rtaware.ros2msg.statistics;

import io.rtaware.core.monitor.CycleOutcome;
import io.rtaware.ros2msg.value.MetricsMessage;
import java.io.IOException;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * The ROS 2 topic statistics of a monitor's run: from the commits and cycle records a recorder or
 * an exporter already receives, one {@code statistics_msgs/msg/MetricsMessage} per window of
 * {@value #WINDOW_NS} ns of world time, per metric, per task and per key, as ROS 2's topic
 * statistics publish them on {@code /statistics} (AVERAGE, MINIMUM, MAXIMUM, STDDEV of the
 * population, SAMPLE_COUNT; a window without samples has count 0 and NaN for the rest).
 *
 * <p>Metrics of a key (ROS 2's own names, with rtaware's commits as the messages):
 * <ul>
 * <li>{@value #MESSAGE_PERIOD}: for each commit whose previous generation's commit is known, the
 *     time since that commit, ms;</li>
 * <li>{@value #MESSAGE_AGE}: for each cycle of a consumer that copied in a generation it did not
 *     hold in its previous cycle (a receipt, in ROS 2's terms), the cycle's start minus that
 *     generation's commit time, ms.</li>
 * </ul>
 * Metrics of a task (rtaware's additions), one sample per cycle unless said otherwise:
 * <ul>
 * <li>{@value #RELEASE_LATENESS}: start minus scheduled release, ms (0 for continuous tasks,
 *     released when they start; never below 0, as in the run's report and the recorded
 *     {@code TaskCycle});</li>
 * <li>{@value #EXECUTION_TIME}: end minus start, ms;</li>
 * <li>{@value #INPUT_AGE}: the cycle's start minus the commit time of the oldest value it held
 *     among its inputs (cycles whose inputs were never written give no sample), ms;</li>
 * <li>{@value #DEADLINE_MISSES}: one sample per release accounted for: 1 for a cycle that missed
 *     its deadline and for each release skipped, 0 for a cycle that met it (a cycle that threw
 *     gives none), unit {@value #COUNT}; so AVERAGE is the fraction of releases missed and
 *     SAMPLE_COUNT the releases.</li>
 * </ul>
 *
 * <p>Windows are {@code [origin + k * WINDOW_NS, origin + (k + 1) * WINDOW_NS)} of world time (the
 * monitor's clock, so at a time scale of 10 a window lasts 0.1 s of wall time); a sample belongs
 * to the window holding its time: a commit's time, a cycle's end, the time skipped releases were
 * reported. The stamps of a message are its window's bounds plus {@code stampOffsetNs} (the
 * Unix-epoch time of world time 0). A window is published, all its messages at once, as soon as
 * its samples can all have arrived: once every task that reported within the last
 * {@code graceNs} has reported a time past its end, and at the latest once the newest time seen
 * (or the clock given) is {@code graceNs} past its end; both judged at one {@link #drained} and
 * acted on at the next, so that what was handed over before a record that passed the end (a
 * commit, drained from another ring, just before the cycle that made it) is in. A record that arrives
 * after its window was published is counted ({@link #lateRecords()}), never put in another
 * window.
 *
 * <p>Ages need the commit time of the generation a cycle held: kept for the latest
 * {@value #COMMIT_HISTORY} commits of each key. A cycle record that names a generation whose
 * commit has not arrived yet (its producer hands the commit over after the consumer could read
 * it) waits, up to {@value #PENDING} of them, until it arrives; an age whose commit was dropped
 * (a full ring) or is too old, or still missing when its window is published, is counted
 * ({@link #unmatchedAges()}). Keys given as null are not followed: no commits, no metrics, and
 * inputs of them are left out of {@value #INPUT_AGE}.
 *
 * <p>Single-threaded: the owner's thread (a recorder's writer, an exporter's loop) calls every
 * method. All storage is allocated here; the calls allocate nothing.
 */
public final class TimingStatistics {

    /** A window's length: one second of world time, as ROS 2's default statistics period. */
    public static final long WINDOW_NS = 1_000_000_000L;
    /** Metric of a key: the time between consecutive commits. */
    public static final String MESSAGE_PERIOD = "message_period";
    /** Metric of a key: how old a value was when a consumer copied it in as new. */
    public static final String MESSAGE_AGE = "message_age";
    /** Metric of a task: start minus scheduled release. */
    public static final String RELEASE_LATENESS = "release_lateness";
    /** Metric of a task: end minus start. */
    public static final String EXECUTION_TIME = "execution_time";
    /** Metric of a task: the age of the oldest input a cycle held at its start. */
    public static final String INPUT_AGE = "input_age";
    /** Metric of a task: 1 per release missed, 0 per release met. */
    public static final String DEADLINE_MISSES = "deadline_misses";
    /** The unit of the time metrics. */
    public static final String MS = "ms";
    /** The unit of {@value #DEADLINE_MISSES}. */
    public static final String COUNT = "count";
    /** Commits of each key whose times are kept for ages. */
    public static final int COMMIT_HISTORY = 1024;
    /** Cycle records that can wait for their inputs' commits at once. */
    public static final int PENDING = 256;

    private static final String[] TASK_METRICS = {RELEASE_LATENESS, EXECUTION_TIME, INPUT_AGE, DEADLINE_MISSES};
    private static final String[] TASK_UNITS = {MS, MS, MS, COUNT};
    private static final String[] KEY_METRICS = {MESSAGE_PERIOD, MESSAGE_AGE};
    private static final int LATENESS = 0;
    private static final int EXECUTION = 1;
    private static final int INPUT = 2;
    private static final int MISSES = 3;
    private static final int PERIOD = 0;
    private static final int AGE = 1;
    /** Windows open at once (the oldest unpublished and the ones after it). */
    private static final int BANKS = 4;
    private static final long NS_PER_MS = 1_000_000L;
    private static final int HISTORY_MASK = COMMIT_HISTORY - 1;

    private final String[] taskNames;
    private final String[] keyNames;
    /** Key index of each task's inputs, -1 for a key not followed. */
    private final int[][] inputKeys;
    /** [bank][task * 4 + metric]. */
    private final Moments[][] taskMoments;
    /** [bank][key * 2 + metric]. */
    private final Moments[][] keyMoments;
    private final long[][] commitTimes;
    private final long[][] commitGenerations;
    private final long[] newestGeneration;
    /** The generation each task's input held in its previous cycle. */
    private final long[][] heldGenerations;
    /** Each task's latest reported time, or MIN_VALUE before its first report. */
    private final long[] latestNs;
    private final int[] pendingTask = new int[PENDING];
    private final long[] pendingStartNs = new long[PENDING];
    private final long[] pendingEndNs = new long[PENDING];
    private final long[][] pendingGenerations;
    private final boolean[][] pendingNew;
    private int pendingCount;
    private final MetricsMessage message = new MetricsMessage(5);
    private final MetricsSink sink;
    private final long originNs;
    private final long stampOffsetNs;
    private final long graceNs;
    /** The oldest window not published yet. */
    private long openWindow;
    private long newestNs = Long.MIN_VALUE;
    /**
     * Windows that ended by this are published at the next {@link #drained}: the least latest
     * time of the tasks active at the previous one, or its newest time (or clock) less the
     * grace, whichever is later.
     */
    private long horizonNs = Long.MIN_VALUE;
    private long late;
    private long unmatched;
    private long windows;
    private long messages;

    /**
     * @param taskNames task names by task index
     * @param taskInputs each task's input key names, in the order of the generations its cycle
     *     records give
     * @param keyNames key names by key index; a null entry is a key not followed
     * @param originNs the world time the first window starts at
     * @param stampOffsetNs added to world time to make the messages' stamps (the Unix-epoch time
     *     of world time 0)
     * @param graceNs world time after a window's end after which it is published even if a task
     *     has not reported past it
     * @param sink where every message goes
     */
    public TimingStatistics(List<String> taskNames, List<List<String>> taskInputs, List<String> keyNames,
                            long originNs, long stampOffsetNs, long graceNs, MetricsSink sink) {
        if (taskInputs.size() != taskNames.size()) {
            throw new IllegalArgumentException(taskNames.size() + " tasks but " + taskInputs.size() + " input lists");
        }
        if (graceNs < 0) {
            throw new IllegalArgumentException("grace must not be negative, got " + graceNs + " ns");
        }
        this.taskNames = taskNames.toArray(new String[0]);
        this.keyNames = keyNames.toArray(new String[0]);
        this.sink = Objects.requireNonNull(sink, "sink");
        this.originNs = originNs;
        this.stampOffsetNs = stampOffsetNs;
        this.graceNs = graceNs;
        int tasks = this.taskNames.length;
        int keys = this.keyNames.length;
        inputKeys = new int[tasks][];
        heldGenerations = new long[tasks][];
        int mostInputs = 0;
        for (int t = 0; t < tasks; t++) {
            List<String> inputs = taskInputs.get(t);
            inputKeys[t] = new int[inputs.size()];
            heldGenerations[t] = new long[inputs.size()];
            for (int i = 0; i < inputs.size(); i++) {
                inputKeys[t][i] = keyNames.indexOf(inputs.get(i));
            }
            mostInputs = Math.max(mostInputs, inputs.size());
        }
        latestNs = new long[tasks];
        Arrays.fill(latestNs, Long.MIN_VALUE);
        taskMoments = new Moments[BANKS][tasks * TASK_METRICS.length];
        keyMoments = new Moments[BANKS][keys * KEY_METRICS.length];
        for (int b = 0; b < BANKS; b++) {
            fill(taskMoments[b]);
            fill(keyMoments[b]);
        }
        commitTimes = new long[keys][];
        commitGenerations = new long[keys][];
        for (int k = 0; k < keys; k++) {
            if (this.keyNames[k] != null) {
                commitTimes[k] = new long[COMMIT_HISTORY];
                commitGenerations[k] = new long[COMMIT_HISTORY];
            }
        }
        newestGeneration = new long[keys];
        pendingGenerations = new long[PENDING][mostInputs];
        pendingNew = new boolean[PENDING][mostInputs];
    }

    private static void fill(Moments[] all) {
        for (int i = 0; i < all.length; i++) {
            all[i] = new Moments();
        }
    }

    // ---------------------------------------------------------------- what the owner hands over

    /**
     * A commit of a key (in generation order per key).
     *
     * @param key the key's index
     * @param generation its generation (1, 2, ...)
     * @param timeNs world time of the commit
     * @throws IOException if publishing a window this forces out fails
     */
    public void commit(int key, long generation, long timeNs) throws IOException {
        if (key >= keyNames.length || keyNames[key] == null) {
            return;
        }
        newestNs = Math.max(newestNs, timeNs);
        int bank = bankFor(timeNs);
        long[] times = commitTimes[key];
        long[] generations = commitGenerations[key];
        int previous = (int) ((generation - 1) & HISTORY_MASK);
        if (bank < 0) {
            late++;
        } else if (generation > 1 && generations[previous] == generation - 1) {
            keyMoments[bank][key * KEY_METRICS.length + PERIOD].add(ms(timeNs - times[previous]));
        }
        int slot = (int) (generation & HISTORY_MASK);
        times[slot] = timeNs;
        generations[slot] = generation;
        newestGeneration[key] = Math.max(newestGeneration[key], generation);
    }

    /**
     * A finished cycle (in order per task).
     *
     * @param task the task's index
     * @param outcome how it ended
     * @param releaseNs its scheduled release (its start, for continuous tasks)
     * @param startNs its start, when its inputs were copied in
     * @param endNs its end
     * @param inputGenerations the generation each input held, in the task's input order (0: never
     *     written); read during the call only
     * @throws IOException if publishing a window this forces out fails
     */
    public void cycle(int task, CycleOutcome outcome, long releaseNs, long startNs, long endNs,
                      long[] inputGenerations) throws IOException {
        reported(task, endNs);
        int bank = bankFor(endNs);
        int[] keys = inputKeys[task];
        long[] held = heldGenerations[task];
        boolean room = pendingCount < PENDING;
        long[] generations = room ? pendingGenerations[pendingCount] : null;
        boolean[] isNew = room ? pendingNew[pendingCount] : null;
        boolean anyInput = false;
        boolean waits = false;
        int receipts = 0;
        for (int i = 0; i < keys.length; i++) {
            long g = inputGenerations == null ? 0 : inputGenerations[i];
            boolean fresh = g != held[i];
            held[i] = g;
            if (keys[i] < 0) {
                g = 0; // a key not followed: left out
            }
            anyInput |= g != 0;
            receipts += g != 0 && fresh ? 1 : 0;
            waits |= g != 0 && g > newestGeneration[keys[i]];
            if (room) {
                generations[i] = g;
                isNew[i] = fresh;
            }
        }
        if (bank < 0) {
            late++;
            return;
        }
        Moments[] m = taskMoments[bank];
        int base = task * TASK_METRICS.length;
        m[base + LATENESS].add(ms(Math.max(0, startNs - releaseNs)));
        m[base + EXECUTION].add(ms(endNs - startNs));
        if (outcome != CycleOutcome.ERROR) {
            m[base + MISSES].add(outcome == CycleOutcome.MISS ? 1 : 0);
        }
        if (!anyInput) {
            return;
        }
        if (!room) {
            unmatched += 1 + receipts; // no room to keep the record: its input age and receipts are lost
            return;
        }
        pendingTask[pendingCount] = task;
        pendingStartNs[pendingCount] = startNs;
        pendingEndNs[pendingCount] = endNs;
        if (waits) {
            pendingCount++;
        } else {
            ages(pendingCount);
        }
    }

    /**
     * Releases skipped because the task was still running: each is a missed release.
     *
     * @param task the task's index
     * @param releases how many
     * @param timeNs world time they were reported
     * @throws IOException if publishing a window this forces out fails
     */
    public void skipped(int task, long releases, long timeNs) throws IOException {
        reported(task, timeNs);
        int bank = bankFor(timeNs);
        if (bank < 0) {
            late++;
            return;
        }
        Moments misses = taskMoments[bank][task * TASK_METRICS.length + MISSES];
        for (long i = 0; i < releases; i++) {
            misses.add(1);
        }
    }

    /**
     * Called after each batch handed over (a drain of the rings): settles the cycles waiting for
     * commits that have arrived, then publishes every window whose samples can all have arrived.
     *
     * @param clockNs the world time now, or {@link Long#MIN_VALUE} for an owner without a clock
     *     (a recorder, which goes by the times it is handed)
     * @return messages published
     * @throws IOException if publishing fails
     */
    public int drained(long clockNs) throws IOException {
        settle();
        long before = messages;
        publishEndedBy(horizonNs);
        long seen = Math.max(newestNs, clockNs);
        long fallback = seen == Long.MIN_VALUE ? Long.MIN_VALUE : seen - graceNs;
        long ready = Long.MAX_VALUE;
        for (long t : latestNs) {
            if (t != Long.MIN_VALUE && t >= fallback) {
                ready = Math.min(ready, t);
            }
        }
        horizonNs = ready == Long.MAX_VALUE ? fallback : Math.max(ready, fallback);
        return (int) (messages - before);
    }

    /**
     * Called once everything has been handed over: publishes every window that ended by the
     * newest time seen or {@code clockNs}; the window still running then is not published (its
     * second is not complete).
     *
     * @param clockNs the world time now, or {@link Long#MIN_VALUE} without a clock
     * @return messages published
     * @throws IOException if publishing fails
     */
    public int finish(long clockNs) throws IOException {
        settle();
        long before = messages;
        publishEndedBy(Math.max(newestNs, clockNs));
        return (int) (messages - before);
    }

    // ---------------------------------------------------------------- what it tells

    /**
     * @return records (commits, cycles, reports of skipped releases) that arrived after their
     *     window had been published: their samples are in no message
     */
    public long lateRecords() {
        return late;
    }

    /** @return ages that could not be measured: their commit was dropped, too old or still missing */
    public long unmatchedAges() {
        return unmatched;
    }

    /** @return windows published */
    public long windowsPublished() {
        return windows;
    }

    /** @return messages published */
    public long messagesPublished() {
        return messages;
    }

    /**
     * @return the world time the next window to publish starts at; its messages, still to come,
     *     will be stamped and logged at this plus {@link #WINDOW_NS} (a sink in log-time order
     *     holds back what is later)
     */
    public long nextWindowStartNs() {
        return originNs + openWindow * WINDOW_NS;
    }

    // ---------------------------------------------------------------- the rules

    private void reported(int task, long timeNs) {
        latestNs[task] = Math.max(latestNs[task], timeNs);
        newestNs = Math.max(newestNs, timeNs);
    }

    /**
     * The bank of the open window holding {@code timeNs}. A waiting cycle's window is open: it
     * was when the cycle arrived, and windows are published only after their waiting cycles
     * have been given up.
     */
    private int openBank(long timeNs) {
        long window = Math.floorDiv(timeNs - originNs, WINDOW_NS);
        if (window < openWindow || window >= openWindow + BANKS) {
            throw new IllegalStateException("window " + window + " is not open (" + openWindow + " to "
                    + (openWindow + BANKS - 1) + ")");
        }
        return (int) Math.floorMod(window, (long) BANKS);
    }

    /**
     * The bank of the window holding {@code timeNs}, publishing older windows first if it lies
     * beyond the banks; -1 if that window was published already.
     */
    private int bankFor(long timeNs) throws IOException {
        long window = Math.floorDiv(timeNs - originNs, WINDOW_NS);
        if (window < openWindow) {
            return -1;
        }
        while (window >= openWindow + BANKS) {
            publishOpenWindow();
        }
        return (int) Math.floorMod(window, (long) BANKS);
    }

    /** Measures the ages of the cycle record in pending slot {@code p} (whose commits are all in, or never will be). */
    private void ages(int p) {
        int bank = openBank(pendingEndNs[p]);
        int task = pendingTask[p];
        int[] keys = inputKeys[task];
        long[] generations = pendingGenerations[p];
        boolean[] isNew = pendingNew[p];
        long startNs = pendingStartNs[p];
        long oldest = Long.MIN_VALUE;
        boolean known = true;
        for (int i = 0; i < keys.length; i++) {
            long g = generations[i];
            if (g == 0) {
                continue;
            }
            int key = keys[i];
            int slot = (int) (g & HISTORY_MASK);
            if (commitGenerations[key][slot] != g) {
                known = false;
                if (isNew[i]) {
                    unmatched++;
                }
                continue;
            }
            long ageNs = startNs - commitTimes[key][slot];
            oldest = Math.max(oldest, ageNs);
            if (isNew[i]) {
                keyMoments[bank][key * KEY_METRICS.length + AGE].add(ms(ageNs));
            }
        }
        if (known) {
            taskMoments[bank][task * TASK_METRICS.length + INPUT].add(ms(oldest));
        } else {
            unmatched++;
        }
    }

    /** Measures every waiting cycle whose commits have all arrived. */
    private void settle() {
        int kept = 0;
        for (int p = 0; p < pendingCount; p++) {
            if (waiting(p)) {
                moveTo(p, kept++);
            } else {
                ages(p);
            }
        }
        pendingCount = kept;
    }

    private boolean waiting(int p) {
        int[] keys = inputKeys[pendingTask[p]];
        long[] generations = pendingGenerations[p];
        for (int i = 0; i < keys.length; i++) {
            if (generations[i] != 0 && generations[i] > newestGeneration[keys[i]]) {
                return true;
            }
        }
        return false;
    }

    /** Moves pending slot {@code from} to {@code to} (swapping the arrays, so nothing is allocated). */
    private void moveTo(int from, int to) {
        if (from == to) {
            return;
        }
        pendingTask[to] = pendingTask[from];
        pendingStartNs[to] = pendingStartNs[from];
        pendingEndNs[to] = pendingEndNs[from];
        long[] g = pendingGenerations[to];
        pendingGenerations[to] = pendingGenerations[from];
        pendingGenerations[from] = g;
        boolean[] n = pendingNew[to];
        pendingNew[to] = pendingNew[from];
        pendingNew[from] = n;
    }

    private void publishEndedBy(long horizonNs) throws IOException {
        while (horizonNs != Long.MIN_VALUE && originNs + (openWindow + 1) * WINDOW_NS <= horizonNs) {
            publishOpenWindow();
        }
    }

    /**
     * Publishes the oldest open window: the cycles still waiting for a commit of it are counted
     * as unmatched first; then one message per task and metric, one per key and metric.
     */
    private void publishOpenWindow() throws IOException {
        long startNs = originNs + openWindow * WINDOW_NS;
        long stopNs = startNs + WINDOW_NS;
        int kept = 0;
        for (int p = 0; p < pendingCount; p++) {
            if (pendingEndNs[p] < stopNs) {
                unmatched += ungettable(p);
            } else {
                moveTo(p, kept++);
            }
        }
        pendingCount = kept;
        int bank = (int) Math.floorMod(openWindow, (long) BANKS);
        for (int t = 0; t < taskNames.length; t++) {
            for (int m = 0; m < TASK_METRICS.length; m++) {
                publish(taskNames[t], TASK_METRICS[m], TASK_UNITS[m], taskMoments[bank][t * TASK_METRICS.length + m],
                        startNs, stopNs);
            }
        }
        for (int k = 0; k < keyNames.length; k++) {
            if (keyNames[k] != null) {
                for (int m = 0; m < KEY_METRICS.length; m++) {
                    publish(keyNames[k], KEY_METRICS[m], MS, keyMoments[bank][k * KEY_METRICS.length + m], startNs,
                            stopNs);
                }
            }
        }
        openWindow++; // only now: until its last message is out, the window is the next to publish
        windows++;
    }

    /** @return the ages a waiting cycle record would have given: its input_age and its new inputs */
    private int ungettable(int p) {
        int n = 1;
        boolean[] isNew = pendingNew[p];
        long[] generations = pendingGenerations[p];
        for (int i = 0; i < inputKeys[pendingTask[p]].length; i++) {
            if (generations[i] != 0 && isNew[i]) {
                n++;
            }
        }
        return n;
    }

    private void publish(String source, String metric, String unit, Moments moments, long startNs, long stopNs)
            throws IOException {
        message.clear();
        message.measurementSourceName.append(source);
        message.metricsSource.append(metric);
        message.unit.append(unit);
        message.windowStartNs = startNs + stampOffsetNs;
        message.windowStopNs = stopNs + stampOffsetNs;
        moments.writeTo(message);
        moments.reset();
        sink.publish(message, stopNs);
        messages++;
    }

    private static double ms(long ns) {
        return ns / (double) NS_PER_MS;
    }
}
