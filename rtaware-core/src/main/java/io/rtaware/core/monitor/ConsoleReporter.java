package io.rtaware.core.monitor;

import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.time.Clock;
import io.rtaware.core.time.SystemClock;
import java.io.PrintStream;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.AtomicReferenceArray;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.SleepingMillisIdleStrategy;

/**
 * Prints live deadline misses, stale runs, expired reads, task errors and adaptive period
 * changes, at a rate a person can read: per task, the first line at once, the next after a
 * second, and while the events keep coming the wait doubles up to {@value #LONGEST_INTERVAL_S} s
 * (a task missing throughout a 30 s run prints 6 lines, not 30); after a calm spell it is back to a
 * second. Each line carries the count of everything folded into it since the previous line and the
 * span it covers ({@code 37 deadline misses in the last 4.0 s}): counts are never dropped, only
 * held back, and {@link #flush()} prints what is held back (at the end of a run).
 *
 * <p>Across tasks, at most {@value #TASK_LINES_PER_SECOND} task lines are printed in a wall
 * second. When more tasks are due (hundreds of tasks missing together), the rest fold into one
 * line a second that says how many tasks it covers, their counts together and the task with the
 * most misses ({@code [rtaware] 4117 more tasks: 9311 deadline misses; most misses: t802, 4 (...)}).
 * A flood of misses then costs a few lines, not a line per task: thousands of lines a second
 * would hide the cause and take the CPU and memory the tasks need.
 *
 * <p>Events only bump counters (no allocation, no I/O on task threads); a daemon thread of
 * the reporter's own prints every {@value #POLL_MS} ms, the lines' text built by
 * {@link ConsoleLines}, a class of its own so that none of it is resolved on a task thread.
 * {@link #flush()} prints what is left,
 * e.g. before the termination summary. A fault of that thread goes to the framework error
 * handler of the monitor the reporter listens to, and is counted there
 * ({@link Monitor#frameworkErrors()}). Thread-safe.
 */
public final class ConsoleReporter implements MonitorListener, AutoCloseable {

    private static final int POLL_MS = 100;
    private static final long LINE_INTERVAL_NS = 1_000_000_000L;
    /** The longest wait between two lines of one task while its events keep coming, s. */
    static final int LONGEST_INTERVAL_S = 8;
    /** Most task lines in one wall second, over all tasks; the rest fold into one line a second. */
    static final int TASK_LINES_PER_SECOND = 10;
    private static final int MISSES = 0;
    private static final int SKIPPED = 1;
    private static final int STALE = 2;
    private static final int EXPIRED = 3;
    private static final int ERRORS = 4;
    private static final int PERIOD_CHANGES = 5;
    private static final int KINDS = 6;
    private static final VarHandle EVENT_BITS = MethodHandles.arrayElementVarHandle(long[].class);

    private final PrintStream out;
    private final Clock wallClock;
    private final boolean includeStale;
    private final AtomicLongArray pending;
    private final AtomicLongArray lastMissDetectedNs;
    private final AtomicLongArray lastMissDeadlineNs;
    private final AtomicReferenceArray<Throwable> lastError;
    private final AtomicReferenceArray<PeriodChange> lastPeriodChange;
    private final LinePacer[] pacers;
    /** Wall time the current second of the task-line budget began, and task lines printed in it. */
    private long budgetSecondStartNs = Long.MIN_VALUE;
    private int taskLinesThisSecond;
    /** The counts of the tasks over the budget, since the last fold line (printer's state). */
    private final long[] folded = new long[KINDS];
    /** Per task: whether it is in the next fold line, and its misses and skipped releases there. */
    private final boolean[] inFold;
    private final long[] foldedMissesOf;
    private int foldedTasks;
    /** The wall time of the first report in the next fold line. */
    private long firstFoldNs;
    private final LinePacer foldPacer = new LinePacer(LINE_INTERVAL_NS, LINE_INTERVAL_NS);
    /** The tasks by index. */
    private final TaskInfo[] taskByIndex;
    /**
     * One bit per task, set after each event of the task: the printer looks only at the tasks
     * with a bit set or counts held back, not at every task (10 000 tasks cost milliseconds of a
     * core a look, ten looks a second, taken from the workers). Cleared by the printer.
     */
    private final long[] eventBits;
    /** Printer's: one bit per task whose counts its pacer held back at the last look. */
    private final long[] heldBits;
    /**
     * The wall time of the previous poll, {@link Long#MIN_VALUE} before the first: a task not
     * looked at then had nothing to print then, which is a calm moment if a line was due.
     */
    private long previousPollNs = Long.MIN_VALUE;
    private final AgentThread printer;
    /**
     * Where a fault of the printer's thread goes: the framework's default printer until the
     * monitor this reporter listens to starts, then that monitor's error handler and count.
     */
    private volatile FrameworkFaults faults = new FrameworkFaults(new RateLimitedErrorPrinter());
    /** World time when the first task started running: the origin of printed times. */
    private volatile long originNs = Long.MIN_VALUE;

    /**
     * @param out where lines go
     * @param monitor the monitor whose tasks are reported (register this reporter as its listener
     *     through the builder, then pass the built monitor here)
     * @param includeStale whether stale runs are reported live (they are always in the summary)
     */
    public ConsoleReporter(PrintStream out, List<TaskInfo> monitor, boolean includeStale) {
        this(out, monitor, includeStale, new SystemClock(), true);
    }

    /**
     * @param out where lines go
     * @param monitor the monitor's tasks
     * @param includeStale whether stale runs are reported live
     * @param wallClock the clock of the one-line-per-second limit (wall time, not world time: the
     *     limit protects a person reading a terminal)
     * @param printerThread false for tests, which call {@link #poll()} themselves
     */
    ConsoleReporter(PrintStream out, List<TaskInfo> monitor, boolean includeStale,
                    Clock wallClock, boolean printerThread) {
        this.wallClock = Objects.requireNonNull(wallClock, "wallClock");
        this.out = Objects.requireNonNull(out, "out");
        this.includeStale = includeStale;
        int n = monitor.size();
        this.pending = new AtomicLongArray(n * KINDS);
        this.lastMissDetectedNs = new AtomicLongArray(n);
        this.lastMissDeadlineNs = new AtomicLongArray(n);
        this.lastError = new AtomicReferenceArray<>(n);
        this.lastPeriodChange = new AtomicReferenceArray<>(n);
        this.pacers = new LinePacer[n];
        this.inFold = new boolean[n];
        this.eventBits = new long[(n + 63) >>> 6];
        this.heldBits = new long[eventBits.length];
        this.taskByIndex = new TaskInfo[n];
        for (TaskInfo task : monitor) {
            taskByIndex[task.index()] = task;
        }
        this.foldedMissesOf = new long[n];
        for (int i = 0; i < n; i++) {
            pacers[i] = new LinePacer(LINE_INTERVAL_NS, LONGEST_INTERVAL_S * LINE_INTERVAL_NS);
        }
        linkEventPaths();
        this.printer = printerThread ? AgentThread.start(new Printer(), new SleepingMillisIdleStrategy(POLL_MS),
                error -> faults.report(OffPathText.consoleReporter(), error)) : null;
    }

    /**
     * Makes every atomic operation the event methods use once, changing nothing, before any task
     * runs: the first call of a {@link VarHandle} operation at a place in the code, here or inside
     * the atomic arrays, links it and allocates (a few hundred bytes of method types), and the
     * first miss of a run, which calls most of them, comes on a task's thread in steady state.
     * (The pool's one such call allocated 2256 bytes on a worker in about one Epsilon-guard run in
     * eight; see {@code PooledExecutor}.)
     */
    private void linkEventPaths() {
        if (taskByIndex.length == 0) {
            return;
        }
        pending.incrementAndGet(0);
        pending.addAndGet(0, -1L);
        lastMissDetectedNs.set(0, lastMissDetectedNs.get(0));
        lastMissDeadlineNs.set(0, lastMissDeadlineNs.get(0));
        lastError.set(0, lastError.get(0));
        lastPeriodChange.set(0, lastPeriodChange.get(0));
        long unused = (long) EVENT_BITS.getAndBitwiseOr(eventBits, 0, 0L);
    }

    @Override
    public void onStateChange(TaskInfo task, TaskState state, long nowNs) {
        if (state == TaskState.RUNNING && originNs == Long.MIN_VALUE) {
            originNs = nowNs;
        }
    }

    @Override
    public void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedNs, boolean stillRunning) {
        int i = task.index();
        lastMissDetectedNs.set(i, detectedNs);
        lastMissDeadlineNs.set(i, deadlineNs);
        pending.incrementAndGet(i * KINDS + MISSES);
        markEvent(i);
    }

    @Override
    public void onSkippedReleases(TaskInfo task, long skipped, long nowNs) {
        pending.addAndGet(task.index() * KINDS + SKIPPED, skipped);
        markEvent(task.index());
    }

    @Override
    public void onStaleRun(TaskInfo task, long nowNs) {
        if (includeStale) {
            pending.incrementAndGet(task.index() * KINDS + STALE);
            markEvent(task.index());
        }
    }

    @Override
    public void onExpiredInput(TaskInfo task, String key, long ageNs, long maxAgeNs, long nowNs) {
        pending.incrementAndGet(task.index() * KINDS + EXPIRED);
        markEvent(task.index());
    }

    @Override
    public void onTaskError(TaskInfo task, Throwable error, ErrorPolicy policy, long nowNs) {
        lastError.set(task.index(), error);
        pending.incrementAndGet(task.index() * KINDS + ERRORS);
        markEvent(task.index());
    }

    @Override
    public void onPeriodChange(TaskInfo task, PeriodChange change, long nowNs) {
        lastPeriodChange.set(task.index(), change);
        pending.incrementAndGet(task.index() * KINDS + PERIOD_CHANGES);
        markEvent(task.index());
    }

    /** The printer's loop: a poll every {@value #POLL_MS} ms. */
    private final class Printer implements Agent {
        /**
         * Its thread's name, loaded by the constructor (not initialized at its declaration, where
         * javac would fold it into {@link #roleName()} as a constant that method loads later,
         * unresolved until then; see {@link ConsoleLines}).
         */
        private final String role;

        Printer() {
            role = ThreadNames.CONSOLE;
        }

        @Override
        public int doWork() {
            poll();
            return 0;
        }

        @Override
        public String roleName() {
            return role;
        }
    }

    /** One poll of the printer: prints the tasks whose next line is due. */
    void poll() {
        printDue(false);
    }

    /** Prints every task's folded counts now, regardless of the rate limit. */
    public void flush() {
        printDue(true);
    }

    /** @param monitorFaults the framework faults of the monitor this reporter listens to, as it starts */
    void reportFaultsTo(FrameworkFaults monitorFaults) {
        faults = monitorFaults;
    }

    /** Notes, after its count, that task {@code i} has something to print (any thread). */
    private void markEvent(int i) {
        EVENT_BITS.getAndBitwiseOr(eventBits, i >>> 6, 1L << i);
    }

    /** @return a bit for every task in word {@code word} of {@link #eventBits} (the last word may be partly used) */
    private long taskBitsOf(int word) {
        int tasksInLastWord = taskByIndex.length & 63;
        return word == eventBits.length - 1 && tasksInLastWord != 0 ? (1L << tasksInLastWord) - 1 : -1L;
    }

    private synchronized void printDue(boolean force) {
        long wallNs = wallClock.nanos();
        if (force || budgetSecondStartNs == Long.MIN_VALUE || wallNs - budgetSecondStartNs >= LINE_INTERVAL_NS) {
            budgetSecondStartNs = wallNs;
            taskLinesThisSecond = 0;
        }
        for (int word = 0; word < eventBits.length; word++) {
            // The bit is taken before the counts are read: an event counted later sets it again.
            long bits = (long) EVENT_BITS.getAndSet(eventBits, word, 0L) | heldBits[word];
            heldBits[word] = 0;
            if (force) {
                bits = taskBitsOf(word);
            }
            while (bits != 0) {
                int i = (word << 6) + Long.numberOfTrailingZeros(bits);
                bits &= bits - 1;
                look(i, wallNs, force);
            }
        }
        previousPollNs = wallNs;
        if (foldedTasks > 0 && (force || foldPacer.due(wallNs))) {
            foldPacer.printed(wallNs);
            out.println(foldLine(wallNs - firstFoldNs));
            Arrays.fill(folded, 0);
            Arrays.fill(inFold, false);
            Arrays.fill(foldedMissesOf, 0);
            foldedTasks = 0;
        }
    }

    /** Prints task {@code i}'s line if it is due and has something, or folds it, or holds it back. */
    private void look(int i, long wallNs, boolean force) {
        if (previousPollNs != Long.MIN_VALUE) {
            pacers[i].calmIfDueAt(previousPollNs);
        }
        if (!force && !pacers[i].due(wallNs)) {
            if (hasPending(i)) {
                heldBits[i >>> 6] |= 1L << i;
            }
            return;
        }
        long misses = pending.getAndSet(i * KINDS + MISSES, 0);
        long skipped = pending.getAndSet(i * KINDS + SKIPPED, 0);
        long stale = pending.getAndSet(i * KINDS + STALE, 0);
        long expired = pending.getAndSet(i * KINDS + EXPIRED, 0);
        long errors = pending.getAndSet(i * KINDS + ERRORS, 0);
        long changes = pending.getAndSet(i * KINDS + PERIOD_CHANGES, 0);
        if (misses + skipped + stale + expired + errors + changes == 0) {
            if (!force) {
                pacers[i].calm();
            }
            return;
        }
        long spanNs = pacers[i].printed(wallNs);
        if (taskLinesThisSecond < TASK_LINES_PER_SECOND) {
            taskLinesThisSecond++;
            out.println(taskLine(i, misses, skipped, stale, expired, errors, changes, spanNs));
        } else {
            fold(i, wallNs, misses, skipped, stale, expired, errors, changes);
        }
    }

    /** @return whether task {@code i} has counts no line has printed yet */
    private boolean hasPending(int i) {
        for (int kind = 0; kind < KINDS; kind++) {
            if (pending.get(i * KINDS + kind) != 0) {
                return true;
            }
        }
        return false;
    }

    /** Adds one task's counts, over the budget, to the next fold line. */
    private void fold(int i, long wallNs, long misses, long skipped, long stale, long expired, long errors,
                      long changes) {
        if (foldedTasks == 0) {
            firstFoldNs = wallNs;
        }
        if (!inFold[i]) {
            inFold[i] = true;
            foldedTasks++;
        }
        foldedMissesOf[i] += misses + skipped;
        folded[MISSES] += misses;
        folded[SKIPPED] += skipped;
        folded[STALE] += stale;
        folded[EXPIRED] += expired;
        folded[ERRORS] += errors;
        folded[PERIOD_CHANGES] += changes;
    }

    /** @return the line of the tasks over the budget, covering {@code spanNs} of wall time */
    private String foldLine(long spanNs) {
        int most = -1;
        for (int i = 0; i < foldedMissesOf.length; i++) {
            if (foldedMissesOf[i] > 0 && (most < 0 || foldedMissesOf[i] > foldedMissesOf[most])) {
                most = i;
            }
        }
        return ConsoleLines.foldLine(foldedTasks, folded[MISSES], folded[SKIPPED], folded[STALE], folded[EXPIRED],
                folded[ERRORS], folded[PERIOD_CHANGES], spanNs, most < 0 ? null : taskByIndex[most].name(),
                most < 0 ? 0 : foldedMissesOf[most], TASK_LINES_PER_SECOND);
    }

    private String taskLine(int i, long misses, long skipped, long stale, long expired, long errors, long changes,
                            long spanNs) {
        long origin = originNs == Long.MIN_VALUE ? 0 : originNs;
        return ConsoleLines.taskLine(taskByIndex[i].name(), misses, skipped, stale, expired, errors, spanNs,
                (lastMissDetectedNs.get(i) - origin) / 1e9, (lastMissDeadlineNs.get(i) - origin) / 1e9,
                lastError.get(i), changes, lastPeriodChange.get(i));
    }

    /** Stops the printer thread, then prints what is left. */
    @Override
    public void close() {
        if (printer != null) {
            printer.close();
        }
        flush();
    }
}
