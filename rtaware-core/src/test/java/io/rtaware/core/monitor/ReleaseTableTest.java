package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The release table's numbers, row by row: the grid and its skip rule, re-anchoring, the next
 * release, and the deadline token's one report per miss. The rules that use them are tested
 * through the monitor on the manual clock ({@code PeriodicTimingTest}, {@code AdaptivePeriodTest}).
 */
class ReleaseTableTest {

    private static final long MS = 1_000_000;

    @Test
    void aRowStartsWithNoReleaseAndNothingPublished() {
        ReleaseTable table = new ReleaseTable(2);
        assertEquals(TaskRuntime.NEVER, table.nextReleaseNs(1));
        assertEquals(TaskRuntime.NEVER, table.nextDeadlineNs(1));
        assertEquals(-1, table.pendingIndex(1));
        assertEquals(-1, table.runningCycle(1));
    }

    @Test
    void releasesAndDeadlinesLieOnTheAnchoredGrid() {
        ReleaseTable table = new ReleaseTable(1);
        table.define(0, 10 * MS, 4 * MS);
        table.anchor(0, 3 * MS);
        assertEquals(3 * MS, table.releaseNs(0, 0));
        assertEquals(53 * MS, table.releaseNs(0, 5));
        assertEquals(57 * MS, table.deadlineOf(0, 5));
        assertEquals(10 * MS, table.periodNs(0));
        assertEquals(4 * MS, table.deadlineNs(0));
        assertEquals(3 * MS, table.baseNs(0));
    }

    @Test
    void theSkipRuleGoesToTheFirstGridPointAtOrAfterTheEnd() {
        ReleaseTable table = new ReleaseTable(1);
        table.define(0, 10 * MS, 10 * MS);
        table.anchor(0, 0);
        assertEquals(1, table.nextAfter(0, 0, 9 * MS), "ended before the next grid point");
        assertEquals(1, table.nextAfter(0, 0, 10 * MS), "ended exactly on it: not skipped");
        assertEquals(2, table.nextAfter(0, 0, 10 * MS + 1), "overran it: the next one at or after the end");
        assertEquals(4, table.nextAfter(0, 1, 35 * MS));
    }

    @Test
    void reanchoringKeepsReleaseNAndFollowsTheNewPeriodAfterIt() {
        ReleaseTable table = new ReleaseTable(1);
        table.define(0, 10 * MS, 10 * MS);
        table.anchor(0, 0);
        table.reanchor(0, 4, 20 * MS, 15 * MS);
        assertEquals(40 * MS, table.releaseNs(0, 4));
        assertEquals(60 * MS, table.releaseNs(0, 5));
        assertEquals(75 * MS, table.deadlineOf(0, 5));
        assertEquals(6, table.nextAfter(0, 4, 61 * MS), "the skip rule on the new grid");
    }

    @Test
    void theNextReleaseAndItsDeadline() {
        ReleaseTable table = new ReleaseTable(1);
        table.define(0, 10 * MS, 7 * MS);
        table.anchor(0, 0);
        table.next(0, 3, table.releaseNs(0, 3));
        assertEquals(3, table.nextIndex(0));
        assertEquals(30 * MS, table.nextReleaseNs(0));
        assertEquals(37 * MS, table.nextDeadlineNs(0));
        table.publishPendingIndex(0, 3);
        assertEquals(3, table.pendingIndex(0));
        table.next(0, 3, TaskRuntime.NEVER);
        assertEquals(TaskRuntime.NEVER, table.nextDeadlineNs(0), "never released again");
    }

    @Test
    void aMissIsClaimedOnceEitherByTheWatchdogOrByTheCycle() {
        ReleaseTable table = new ReleaseTable(1);
        table.startCycle(0, 7);
        assertEquals(7, table.runningCycle(0));
        assertFalse(table.claimCycle(0, 6), "not the running cycle");
        assertTrue(table.claimCycle(0, 7), "the watchdog claims it");
        assertEquals(-1, table.runningCycle(0));
        assertFalse(table.finishCycle(0, 7), "claimed: the cycle does not report it again");

        table.startCycle(0, 8);
        assertTrue(table.finishCycle(0, 8), "not claimed: the cycle's to report");
        assertFalse(table.claimCycle(0, 8), "ended: nothing for the watchdog");
    }

    @Test
    void aCycleStartedPastItsDeadlineIsNeverSeenRunning() {
        ReleaseTable table = new ReleaseTable(1);
        table.startCycleAlreadyMissed(0, 2);
        assertEquals(-1, table.runningCycle(0));
        assertFalse(table.claimCycle(0, 2));
        assertFalse(table.finishCycle(0, 2));
    }

    @Test
    void rowsAreIndependent() {
        ReleaseTable table = new ReleaseTable(3);
        for (int task = 0; task < 3; task++) {
            table.define(task, (task + 1) * MS, MS);
            table.anchor(task, task * 100 * MS);
            table.next(task, task, table.releaseNs(task, task));
            table.startCycle(task, task);
        }
        for (int task = 0; task < 3; task++) {
            assertEquals(task * 100 * MS + task * (task + 1) * MS, table.nextReleaseNs(task));
            assertEquals(task, table.runningCycle(task));
        }
    }
}
