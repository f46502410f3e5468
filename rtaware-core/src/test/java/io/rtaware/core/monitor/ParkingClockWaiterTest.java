package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.time.Clock;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Where {@link ParkingClockWaiter#sleep} sends a task thread, on a clock that stands still. */
class ParkingClockWaiterTest {

    /** World time fixed at {@link #NOW}, running at twice wall speed (so world ns map to half as many wall ns). */
    private static final long NOW = 1_000_000_000L;

    private static final Clock DOUBLE_SPEED = new Clock() {
        @Override
        public long nanos() {
            return NOW;
        }

        @Override
        public double timeScale() {
            return 2.0;
        }
    };

    private final List<Long> wallTargets = new ArrayList<>();
    private final ParkingClockWaiter waiter = new ParkingClockWaiter(DOUBLE_SPEED, wallTargets::add);
    private final ClockWaiter.Party party = waiter.register(Thread.currentThread());

    @Test
    void aSleepAsksTheSleeperForTheWallInstantTheWorldTargetMapsTo() {
        long before = System.nanoTime();
        party.sleep(NOW + 8_000_000);
        long after = System.nanoTime();
        assertEquals(1, wallTargets.size());
        long target = wallTargets.get(0);
        assertTrue(target >= before + 4_000_000 && target <= after + 4_000_000,
                "8 ms of world time at x2 is 4 ms of wall time from now: " + (target - before));
    }

    @Test
    void oneSleepLastsAtMostAHundredMillisecondsSoAStopIsSeen() {
        long before = System.nanoTime();
        party.sleep(NOW + 60_000_000_000L);
        party.sleep(Long.MAX_VALUE);
        long after = System.nanoTime();
        for (long target : wallTargets) {
            assertTrue(target >= before + 100_000_000 && target <= after + 100_000_000, "capped: " + (target - before));
        }
        assertEquals(2, wallTargets.size());
    }

    @Test
    void aTargetReachedAlreadyDoesNotSleep() {
        party.sleep(NOW);
        party.sleep(NOW - 5);
        assertEquals(List.of(), wallTargets);
    }

    @Test
    void parksNeverUseTheSleeperForAnUnparkMustEndThem() {
        party.park(NOW + 1_000);
        assertEquals(List.of(), wallTargets);
    }
}
