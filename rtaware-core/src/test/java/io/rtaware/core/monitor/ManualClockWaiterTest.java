package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.time.ManualClock;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The idle view tests on a manual clock step by: a party is idle only while it waits for a time
 * still ahead with no wake pending. The case that made stepped tests end early: a thread that
 * looked idle was about to wake (another thread had asked), and the step was taken on what it
 * announced before. Each state here is held still (the waiting thread is not unparked until the
 * test says so), so every assertion is exact.
 */
class ManualClockWaiterTest {

    private final ManualClock clock = new ManualClock();
    private final ManualClockWaiter waiter = new ManualClockWaiter(clock);
    private final AtomicBoolean stop = new AtomicBoolean();
    private Thread sleeper;
    private ManualClockWaiter.ManualParty party;

    /** The sleeper waits for 10 ms, again after every wake-up, until told to stop; a second party is done at once. */
    @BeforeEach
    void startSleeper() {
        sleeper = new Thread(() -> {
            while (!stop.get() && clock.nanos() < ms(10)) {
                party.park(ms(10));
            }
            party.done();
        }, "sleeper");
        party = (ManualClockWaiter.ManualParty) waiter.register(sleeper);
        waiter.register(Thread.currentThread()).done();
        sleeper.start();
    }

    @AfterEach
    void stopSleeper() throws InterruptedException {
        stop.set(true);
        party.wake();
        sleeper.join();
        waiter.close();
    }

    @Test
    void aPartyWaitingForATimeAheadIsIdleAndNamesThatTime() {
        assertEquals(ms(10), waiter.awaitIdleNextWakeNs());
    }

    @Test
    void aWakeRequestedButNotYetSeenMakesTheViewNotIdle() {
        waiter.awaitIdleNextWakeNs();
        // The request is recorded, the sleeper not yet unparked: it has not seen it.
        party.requestWake();
        assertEquals(ManualClockWaiter.NOT_IDLE, waiter.idleNextWakeNs(),
                "the sleeper still announces 10 ms, but a wake is pending: not idle");
        // Once the sleeper wakes and waits again, the view is idle with the same time.
        party.wake();
        assertEquals(ms(10), waiter.awaitIdleNextWakeNs());
    }

    @Test
    void anAdvanceWakesEveryPartyAndAPartyDueIsNotIdle() {
        waiter.awaitIdleNextWakeNs();
        clock.advanceTo(ms(10));
        // The sleeper is due: it returns and is done; until then the view is not idle.
        assertEquals(Long.MAX_VALUE, waiter.awaitIdleNextWakeNs(), "every party done: nothing to wait for");
    }

    @Test
    void anAdvanceShortOfTheTargetLeavesThePartyWaitingForTheSameTime() {
        waiter.awaitIdleNextWakeNs();
        clock.advanceTo(ms(4));
        assertEquals(ms(10), waiter.awaitIdleNextWakeNs());
    }
}
