package io.rtaware.bench.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.netty.util.Timeout;
import io.netty.util.Timer;
import io.netty.util.TimerTask;
import io.rtaware.bench.load.BusyWork;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The netty-wheel row's periodic task on a manual clock: the lateness it records when the wheel
 * fires it, and the delay it re-arms with (to the next grid point, not {@code now + period}).
 * The wheel itself is a recording {@link Timer}: Netty's reads {@code System.nanoTime()}.
 */
class NettyWheelSegmentTest {

    private static final BusyWork WORK = BusyWork.calibrate();
    private static final long PERIOD = 10_000_000;

    private long now;
    private boolean running = true;

    /** Records each timeout asked for. */
    private static final class RecordingTimer implements Timer {
        private long delayNs = -1;
        private int armed;

        @Override
        public Timeout newTimeout(TimerTask task, long delay, TimeUnit unit) {
            delayNs = unit.toNanos(delay);
            armed++;
            return null;
        }

        @Override
        public Set<Timeout> stop() {
            return Set.of();
        }
    }

    @Test
    void aRunIsLateByItsStartMinusTheGridPointAndReArmsForTheNextGridPoint() {
        ReleaseStats stats = new ReleaseStats(PERIOD);
        RecordingTimer timer = new RecordingTimer();
        NettyWheelSegment.Rearming task = new NettyWheelSegment.Rearming(
                new GridTask(1_000_000, PERIOD, 0, WORK, stats, () -> now), timer, () -> running, () -> now);

        task.arm();
        assertEquals(1_000_000, timer.delayNs, "the first release, 1 ms ahead");

        now = 1_700_000; // the wheel fired it 0.7 ms late
        task.run(null);
        assertEquals(1, stats.releases());
        assertEquals(700_000, stats.maxLatenessNs());
        assertEquals(11_000_000 - 1_700_000, timer.delayNs, "re-armed for 11 ms, not 1.7 ms + the period");

        now = 11_000_000 + 2 * PERIOD + 4_000_000; // 35 ms: the 11 ms release runs after two more were due
        task.run(null);
        assertEquals(4, stats.releases(), "two runs, 21 ms and 31 ms skipped");
        assertEquals(3, stats.misses(), "the late run and the two skipped");
        assertEquals(24_000_000, stats.maxLatenessNs());
        assertEquals(41_000_000 - now, timer.delayNs, "the next grid point after the run: 41 ms");

        running = false;
        now = 41_000_000;
        task.run(null);
        assertEquals(5, stats.releases());
        assertEquals(3, timer.armed, "a stopped segment does not re-arm");
    }
}
