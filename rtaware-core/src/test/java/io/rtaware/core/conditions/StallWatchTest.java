package io.rtaware.core.conditions;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** The stall watcher's loop on a clock the test moves: how late it woke, exactly. */
class StallWatchTest {

    @Test
    void keepsTheLongestItWokeLaterThanItAsked() {
        AtomicLong now = new AtomicLong();
        long[] slept = {20_000_000, 20_300_000, 5_020_000_000L, 19_000_000, 21_000_000}; // the 3rd: a 5 s SIGSTOP
        int[] next = {0};
        StallWatch.Watcher watcher = new StallWatch.Watcher(now::get, asked -> {
            assertEquals(StallWatch.INTERVAL_MS * 1_000_000L, asked, "asks for its interval");
            now.addAndGet(slept[next[0]++]);
        });
        watcher.doWork();
        assertEquals(0, watcher.longestLateNs(), "on time");
        watcher.doWork();
        assertEquals(300_000, watcher.longestLateNs());
        watcher.doWork();
        assertEquals(5_000_000_000L, watcher.longestLateNs(), "the stop");
        watcher.doWork(); // woke early (an unpark): not negative, nothing kept
        watcher.doWork();
        assertEquals(5_000_000_000L, watcher.longestLateNs(), "the longest stays");
    }
}
