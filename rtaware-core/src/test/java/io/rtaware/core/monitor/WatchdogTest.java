package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.time.ManualClock;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/**
 * The watchdog's wake-up protocol with a cycle that starts while it scans, on a manual clock:
 * the cycle starts from inside the scan (the slots' callback, on the watchdog's own thread),
 * right after the scan has read that cycle's slot, so the interleaving is the same on every run.
 */
class WatchdogTest {

    private final ManualClock clock = new ManualClock();
    private final ManualClockWaiter waiter = new ManualClockWaiter(clock);
    private final List<String> faults = new CopyOnWriteArrayList<>();

    /**
     * The scan read the slot before the cycle was published there, and the cycle's
     * {@link Watchdog#wakeFor} came before the scan had set its wake time: the scan's end takes
     * the deadline into its wake time. Before, the request compared the deadline with the wake
     * time of the scan before (here none yet: "about to look anyway") and was dropped, and the
     * watchdog slept until another cycle asked (here: never), so a task hung in that cycle was
     * reported only when it returned.
     */
    @Test
    void aCycleThatStartsDuringAScanAfterItsSlotWasReadIsWatchedFromTheScansEnd() {
        AtomicLong publishedDeadlineNs = new AtomicLong(Long.MAX_VALUE);
        Watchdog dog = startOverOneSlot((watchdog, looksBefore, nowNs) -> {
            long seen = publishedDeadlineNs.get();
            if (looksBefore == 0) {
                // The slot has been read: a worker now starts a cycle in it, deadline at 30 ms.
                publishedDeadlineNs.set(ms(30));
                watchdog.wakeFor(ms(30));
            }
            return seen > nowNs ? seen : Long.MAX_VALUE;
        });

        assertEquals(ms(30) + 1, waiter.awaitIdleNextWakeNs(),
                "the first scan saw no cycle, yet the watchdog sleeps only until just after the one that started in it");
        clock.advanceTo(ms(30) + 1);
        assertEquals(Long.MAX_VALUE, waiter.awaitIdleNextWakeNs(), "the second scan found nothing more to watch");
        assertEquals(2, dog.scans(), "one scan at the start, one just after the cycle's deadline");
        dog.stopAndJoin();
        assertEquals(List.of(), faults);
    }

    /**
     * A request during a scan for a deadline later than the earliest the scan finds changes
     * nothing: the watchdog wakes for the earlier one, and a cycle started during a scan costs
     * no scan of its own.
     */
    @Test
    void aLaterDeadlineAskedForDuringAScanLeavesTheWakeTimeAlone() {
        Watchdog dog = startOverOneSlot((watchdog, looksBefore, nowNs) -> {
            if (looksBefore == 0) {
                watchdog.wakeFor(ms(50));
            }
            return ms(20) > nowNs ? ms(20) : Long.MAX_VALUE;
        });

        assertEquals(ms(20) + 1, waiter.awaitIdleNextWakeNs(), "the scan's own earliest deadline, 20 ms");
        assertEquals(1, dog.scans());
        dog.stopAndJoin();
        assertEquals(List.of(), faults);
    }

    /**
     * Cycles whose deadlines come before the watchdog's wake time each ask for a wake; while the
     * first wake has not been taken (the watchdog's thread has not run yet, as a watchdog at
     * normal priority beside real-time workers that keep every CPU), the others send none: its
     * next scan sees them all. Once it has scanned, an earlier deadline wakes it again.
     */
    @Test
    void aWakeNotYetTakenIsNotSentAgain() {
        HeldWakes held = new HeldWakes(waiter);
        Watchdog dog = startOverOneSlot(held, (watchdog, looksBefore, nowNs) -> ms(50) > nowNs ? ms(50) : Long.MAX_VALUE);
        assertEquals(ms(50) + 1, waiter.awaitIdleNextWakeNs(), "the first scan: wake just after 50 ms");

        dog.wakeFor(ms(20));
        dog.wakeFor(ms(20));
        dog.wakeFor(ms(30));
        assertEquals(1, held.wakes.get(), "three cycles before the wake time, one wake while none is taken");

        held.deliver();
        assertEquals(ms(50) + 1, waiter.awaitIdleNextWakeNs(), "the woken watchdog scanned and sleeps again");
        assertEquals(2, dog.scans());
        dog.wakeFor(ms(20));
        assertEquals(2, held.wakes.get(), "after its scan, an earlier deadline wakes it again");
        dog.stopAndJoin();
        assertEquals(List.of(), faults);
    }

    /**
     * The thread setup runs once, on the watchdog's own thread, before its first scan (where a
     * real-time setup raises its priority above the tasks'), with the monitor's task count.
     */
    @Test
    void theThreadSetupRunsOnTheWatchdogsThreadBeforeItsFirstScan() {
        List<String> calls = new CopyOnWriteArrayList<>();
        Watchdog dog = startOverOneSlot(waiter, (watchdog, looksBefore, nowNs) -> {
            calls.add("scan " + watchdog.scans());
            return Long.MAX_VALUE;
        }, new SetupOnly() {
            @Override
            public void onWatchdogStart(int taskCount) {
                calls.add("setup on " + Thread.currentThread().getName() + " for " + taskCount + " tasks");
            }
        });
        assertEquals(Long.MAX_VALUE, waiter.awaitIdleNextWakeNs());
        dog.stopAndJoin();
        assertEquals(List.of("setup on " + ThreadNames.WATCHDOG + " for 7 tasks", "scan 1"), calls);
        assertEquals(List.of(), faults);
    }

    /** A thread setup that throws is reported as a framework fault, and the watchdog watches on. */
    @Test
    void aFaultyThreadSetupIsReportedAndTheWatchdogWatchesOn() {
        Watchdog dog = startOverOneSlot(waiter, (watchdog, looksBefore, nowNs) -> ms(40) > nowNs ? ms(40) : Long.MAX_VALUE,
                new SetupOnly() {
                    @Override
                    public void onWatchdogStart(int taskCount) {
                        throw new IllegalStateException("no priority for you");
                    }
                });
        assertEquals(ms(40) + 1, waiter.awaitIdleNextWakeNs(), "it scanned after the fault");
        dog.stopAndJoin();
        assertEquals(List.of("thread setup of the test watchdog"), faults);
    }

    /** A thread setup that only overrides what a test asks of it. */
    private abstract static class SetupOnly implements ThreadSetup {
        @Override
        public void onTaskThreadStart(TaskInfo task, int rmRank, int taskCount) {
        }

        @Override
        public void onPoolWorkerStart(int worker, int rmRank, int taskCount) {
        }
    }

    /**
     * A waiter whose wakes are counted and held back until {@link #deliver}: the woken thread
     * behaves as one that has not been given a CPU yet.
     */
    private static final class HeldWakes implements ClockWaiter {
        private final ClockWaiter inner;
        final AtomicInteger wakes = new AtomicInteger();
        private volatile Party innerParty;

        HeldWakes(ClockWaiter inner) {
            this.inner = inner;
        }

        @Override
        public Party register(Thread thread) {
            Party party = inner.register(thread);
            innerParty = party;
            return new Party() {
                @Override
                public void park(long targetNs) {
                    party.park(targetNs);
                }

                @Override
                public void wake() {
                    wakes.incrementAndGet();
                }

                @Override
                public void done() {
                    party.done();
                }
            };
        }

        /** Delivers the wakes held so far (one unpark). */
        void deliver() {
            innerParty.wake();
        }

        @Override
        public long zeroCycleSpacingNs() {
            return inner.zeroCycleSpacingNs();
        }

        @Override
        public void close() {
            inner.close();
        }
    }

    /** What a look at the one slot returns (and does), on the watchdog's thread. */
    private interface SlotLook {
        long nextDeadlineNs(Watchdog watchdog, int looksBefore, long nowNs);
    }

    /** Starts a watchdog over one slot that never holds a task and whose deadline {@code look} gives. */
    private Watchdog startOverOneSlot(SlotLook look) {
        return startOverOneSlot(waiter, look);
    }

    /** As {@link #startOverOneSlot(SlotLook)}, waiting with {@code through}. */
    private Watchdog startOverOneSlot(ClockWaiter through, SlotLook look) {
        return startOverOneSlot(through, look, null);
    }

    /** As {@link #startOverOneSlot(ClockWaiter, SlotLook)}, with a thread setup. */
    private Watchdog startOverOneSlot(ClockWaiter through, SlotLook look, ThreadSetup setup) {
        AtomicReference<Watchdog> self = new AtomicReference<>();
        AtomicInteger looks = new AtomicInteger();
        Watchdog.Slots slots = new Watchdog.Slots() {
            @Override
            public int count() {
                return 1;
            }

            @Override
            public TaskRuntime taskAt(int slot) {
                return null;
            }

            @Override
            public long nextDeadlineNs(int slot, TaskRuntime task, long nowNs) {
                return look.nextDeadlineNs(self.get(), looks.getAndIncrement(), nowNs);
            }
        };
        Watchdog dog = new Watchdog(clock, through, new FrameworkFaults((source, error) -> faults.add(source)),
                "test watchdog", slots, setup, 7);
        self.set(dog);
        dog.prepare();
        dog.start();
        return dog;
    }
}
