package io.rtaware.core.monitor;

import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.time.Clock;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.concurrent.locks.LockSupport;

/**
 * The watchdog thread of the threaded and pooled executors, which reports misses at the
 * deadline: it sleeps until the earliest deadline that could be missed, wakes just after it,
 * claims the misses of cycles still running past their deadline in its executor's {@link Slots}
 * and finds the next deadline, and sleeps again. Tasks released on time never wake it; a thread
 * that starts a cycle whose deadline comes before the watchdog's wake time wakes it
 * ({@link #wakeFor}).
 *
 * <p>No fault stops it: a scan that throws is reported to the {@link FrameworkFaults} and the
 * watchdog scans again at its next wake. Thread-safe: prepared, started and stopped once, by its
 * executor; {@link #wakeFor} from any thread.
 */
final class Watchdog {

    /**
     * What the watchdog looks at: its executor's slots (a task thread each on the threaded
     * executor, a worker each on the pool), each of which may hold a cycle that can miss its
     * deadline. Allocation-free; called on the watchdog's thread.
     */
    interface Slots {
        /** @return how many slots there are; fixed */
        int count();

        /**
         * @param slot a slot
         * @return the task whose running cycle may be past its deadline in that slot now, or null
         */
        TaskRuntime taskAt(int slot);

        /**
         * @param slot a slot
         * @param task what {@link #taskAt} returned for it, after its misses were claimed
         * @param nowNs the scan's world time
         * @return the earliest deadline of that slot after {@code nowNs} that the watchdog must
         *     wake for (a running cycle's, a waiting release's), or {@link Long#MAX_VALUE} if none
         */
        long nextDeadlineNs(int slot, TaskRuntime task, long nowNs);
    }

    private final Clock clock;
    private final ClockWaiter waiter;
    private final FrameworkFaults faults;
    private final String faultSource;
    private final Slots slots;
    /** Run on its thread before the first scan; null for none. */
    private final ThreadSetup threadSetup;
    /** The number of tasks of the monitor, for {@link ThreadSetup#onWatchdogStart}. */
    private final int taskCount;
    /** Its handle in the waiter; set by {@link #prepare()}, before the thread starts. */
    private ClockWaiter.Party party;
    private volatile boolean running;
    private Thread thread;
    /**
     * The world time it sleeps until; {@link #wakeFor} compares a new cycle's deadline with it.
     * {@link #SCANNING} while it scans (and before its first scan).
     */
    private volatile long wakeNs = SCANNING;
    /** {@link #wakeNs} while the watchdog scans: its wake time is not decided yet. */
    private static final long SCANNING = Long.MIN_VALUE;
    /**
     * The earliest deadline {@link #wakeFor} was asked for while the watchdog scanned
     * ({@link Long#MAX_VALUE}: none): a cycle that started after the scan looked at its slot, which
     * the scan's end takes into its wake time.
     */
    private volatile long requestedDuringScanNs = Long.MAX_VALUE;
    private static final VarHandle REQUESTED_DURING_SCAN_NS;

    static {
        try {
            REQUESTED_DURING_SCAN_NS = MethodHandles.lookup()
                    .findVarHandle(Watchdog.class, "requestedDuringScanNs", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }
    /** Set by {@link #wakeFor} before it wakes the thread; cleared by the thread before each scan. */
    private volatile boolean wakeRequested;
    /** Scans so far; written by the watchdog thread only. */
    private long scans;

    /**
     * @param clock world time
     * @param waiter how it sleeps
     * @param faults where a fault of its scan goes
     * @param faultSource how such a fault names it
     * @param slots what it looks at each wake-up
     * @param threadSetup run on its thread before the first scan ({@link ThreadSetup#onWatchdogStart};
     *     a fault is reported and it watches on); null for none
     * @param taskCount the number of tasks of the monitor
     */
    Watchdog(Clock clock, ClockWaiter waiter, FrameworkFaults faults, String faultSource, Slots slots,
             ThreadSetup threadSetup, int taskCount) {
        this.clock = clock;
        this.waiter = waiter;
        this.faults = faults;
        this.faultSource = faultSource;
        this.slots = slots;
        this.threadSetup = threadSetup;
        this.taskCount = taskCount;
    }

    /** Creates the thread and registers it with the waiter; before any {@link #wakeFor}. */
    void prepare() {
        running = true;
        thread = new Thread(this::watch, ThreadNames.WATCHDOG);
        thread.setDaemon(true);
        thread.setPriority(Thread.MAX_PRIORITY);
        party = waiter.register(thread);
    }

    /** Starts the thread prepared by {@link #prepare()}. */
    void start() {
        thread.start();
    }

    /**
     * Wakes the watchdog if a cycle's deadline comes before its wake time. Call after the cycle is
     * marked running (a volatile write), so that either the watchdog's next scan sees the cycle or
     * this call sees the wake time that scan set; allocation-free.
     *
     * <p>While the watchdog scans, its wake time is not decided, and the scan may already have
     * looked at the slot of the cycle that starts now: the deadline is then left for the scan's
     * end, which wakes no later than it, and looked at again once the wake time is set (before
     * this, a cycle that started during a scan whose slot the scan had passed was not watched
     * until some later cycle woke the watchdog: a task that hung in it was reported only when
     * it returned).
     *
     * <p>A wake already asked for and not yet taken (the watchdog has not begun its next scan,
     * which clears the request first) is not sent again: that scan sees this cycle, whose mark
     * came before this call read the request. Under {@code --realtime} a watchdog at normal
     * priority beside SCHED_FIFO workers that keep both CPUs may not run for a whole drain, and
     * each cycle of the drain woke it again: a fifth of the workers' CPU went to those wake-ups
     * (docs/performance.md).
     *
     * @param deadlineNs the deadline of the cycle that starts now
     */
    void wakeFor(long deadlineNs) {
        long wake = wakeNs;
        if (wake == SCANNING) {
            long requested;
            do {
                requested = requestedDuringScanNs;
            } while (deadlineNs < requested
                    && !REQUESTED_DURING_SCAN_NS.compareAndSet(this, requested, deadlineNs));
            // Either the scan's end reads the request, or this reads the wake time it set.
            wake = wakeNs;
            if (wake == SCANNING) {
                return;
            }
        }
        if (deadlineNs < wake && !wakeRequested) {
            wakeRequested = true;
            party.wake();
        }
    }

    /**
     * Scans, then sleeps until just after the time the scan named (a miss is a cycle still
     * running past its deadline) or until {@link #wakeFor} asks for an earlier look; a park that
     * returns for any other reason (a spurious wake-up, a manual clock's advance) does not cost
     * a scan.
     */
    private void watch() {
        try {
            if (threadSetup != null) {
                try {
                    threadSetup.onWatchdogStart(taskCount);
                } catch (Throwable t) {
                    faults.report(OffPathText.watchdogSetup(faultSource), t);
                }
            }
            while (running) {
                // Cleared before the scan: a request made from here on leads to another scan, or
                // to an earlier wake (a request made during the scan; a cycle that started before
                // these stores is seen by the scan).
                wakeRequested = false;
                requestedDuringScanNs = Long.MAX_VALUE;
                wakeNs = SCANNING;
                scans++;
                long earliest = Long.MAX_VALUE;
                try {
                    earliest = scan(clock.nanos());
                } catch (Throwable fault) {
                    faults.report(faultSource, fault);
                }
                // The wake time is written before the requests are read (see wakeFor).
                wakeNs = earliest;
                long requested = requestedDuringScanNs;
                if (requested < earliest) {
                    earliest = requested;
                    wakeNs = earliest;
                }
                long targetNs = earliest == Long.MAX_VALUE ? Long.MAX_VALUE : earliest + 1;
                while (running && !wakeRequested && clock.nanos() < targetNs) {
                    party.park(targetNs);
                }
            }
        } finally {
            party.done();
        }
    }

    /**
     * The one scan of both executors: claims the misses of the cycles running past their
     * deadline at {@code nowNs}, and names the earliest deadline after it that could still be
     * missed ({@link Long#MAX_VALUE} if none: it then sleeps until woken). Allocation-free.
     */
    private long scan(long nowNs) {
        long earliest = Long.MAX_VALUE;
        for (int slot = 0, n = slots.count(); slot < n; slot++) {
            TaskRuntime task = slots.taskAt(slot);
            if (task != null) {
                task.checkDeadline(nowNs);
            }
            earliest = Math.min(earliest, slots.nextDeadlineNs(slot, task, nowNs));
        }
        return earliest;
    }

    /** @return how many times it has scanned (how often it woke); exact once it has stopped */
    long scans() {
        return scans;
    }

    /** Stops the thread and waits for it (see {@link #joinOrInterrupt}); a no-op if never prepared. */
    void stopAndJoin() {
        running = false;
        if (thread != null) {
            LockSupport.unpark(thread);
            joinOrInterrupt(thread, JOIN_TIMEOUT_MS, faults);
        }
    }

    /** How long a stop waits for one of the executors' threads before interrupting it, ms. */
    static final long JOIN_TIMEOUT_MS = 5_000;

    /**
     * Waits for a thread the executor has asked to stop; after {@code timeoutMs} reports it as a
     * framework fault (to the monitor's error handler, counted), interrupts it and waits as long
     * again. Returns at once for the calling thread itself (a task that stops its own monitor) and
     * keeps the caller's interrupt.
     *
     * @param thread the thread, or null
     * @param timeoutMs how long to wait before the fault and the interrupt ({@link #JOIN_TIMEOUT_MS})
     * @param faults where a thread that did not return is reported
     */
    static void joinOrInterrupt(Thread thread, long timeoutMs, FrameworkFaults faults) {
        if (thread == null || thread == Thread.currentThread()) {
            return;
        }
        try {
            thread.join(timeoutMs);
            if (thread.isAlive()) {
                faults.report(OffPathText.stopping(), OffPathText.didNotStop(thread, timeoutMs));
                thread.interrupt();
                thread.join(timeoutMs);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
