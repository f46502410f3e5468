package io.rtaware.bench.compare;

import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.LongSupplier;
import org.agrona.DeadlineTimerWheel;
import org.agrona.collections.Hashing;
import org.agrona.collections.Long2LongHashMap;

/**
 * Agrona's timer wheel driven the way its users drive it ({@code agrona-wheel}): one thread loops
 * {@link DeadlineTimerWheel#poll} with the current time and, when a poll expired nothing, parks
 * with {@link LockSupport#parkNanos} until the end of the wheel's current tick. The tick is
 * 2^{@value #TICK_SHIFT} ns (1.05 ms: the wheel wants a power of two, and 1 ms is what a user of
 * millisecond periods would pick); the wheel has as many ticks as span the longest period, rounded
 * up to a power of two and at least {@value #MIN_TICKS_PER_WHEEL}, so every timer is due within
 * one turn; each tick's slots start at Agrona's default and grow to the most timers due in one
 * tick. The expiry handler runs the task on the loop's thread and schedules its next grid point
 * ({@link GridTask}), finding the task of a timer id in a {@link Long2LongHashMap}, so a
 * release allocates nothing. A timer expires at the first poll at or after its deadline, and
 * the loop polls at tick boundaries, so a release waits for the end of its tick.
 */
final class AgronaWheelSegment implements SegmentExecutor {

    /** The tick is 2^TICK_SHIFT ns. */
    static final int TICK_SHIFT = 20;
    /** Fewest ticks of the wheel. */
    static final int MIN_TICKS_PER_WHEEL = 16;
    private static final long JOIN_TIMEOUT_MS = 10_000;

    private final BusyWork work;
    private Thread thread;
    private volatile boolean running;

    /** @param work the calibrated busy loop */
    AgronaWheelSegment(BusyWork work) {
        this.work = work;
    }

    @Override
    public String name() {
        return "agrona-wheel";
    }

    @Override
    public void start(List<BenchSpec> specs, List<ReleaseStats> stats) {
        long t0 = System.nanoTime();
        GridTask[] tasks = GridTask.of(specs, stats, t0, work);
        long longestNs = specs.stream().mapToLong(BenchSpec::periodNs).max().orElse(0);
        WheelLoop loop = new WheelLoop(tasks, t0, ticksPerWheel(longestNs), System::nanoTime);
        running = true;
        thread = new Thread(() -> {
            while (running) {
                long parkNs = loop.pollOnce();
                if (parkNs > 0) {
                    LockSupport.parkNanos(parkNs);
                }
            }
        }, "agrona-wheel");
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * @param longestPeriodNs the longest period of the task set
     * @return ticks of a wheel that spans it, a power of two
     */
    static int ticksPerWheel(long longestPeriodNs) {
        long ticks = Math.max(MIN_TICKS_PER_WHEEL, (longestPeriodNs + (1L << TICK_SHIFT) - 1) >> TICK_SHIFT);
        return (int) Math.min(1 << 30, Long.highestOneBit(ticks - 1) << 1);
    }

    @Override
    public long[] helperThreadIds() {
        return new long[] {thread.getId()};
    }

    @Override
    public void stop() throws InterruptedException {
        running = false;
        LockSupport.unpark(thread);
        thread.join(JOIN_TIMEOUT_MS);
    }

    /** The wheel, its timers' tasks and one pass of the loop; the clock is given, so tests step it. */
    static final class WheelLoop implements DeadlineTimerWheel.TimerHandler {
        private static final long NO_TASK = -1;

        private final DeadlineTimerWheel wheel;
        private final Long2LongHashMap taskOfTimer;
        private final GridTask[] tasks;
        private final LongSupplier nanoTime;

        /**
         * Schedules every task's first release.
         *
         * @param tasks the tasks
         * @param startNs the wheel's start time
         * @param ticksPerWheel ticks of the wheel, a power of two
         * @param nanoTime the clock
         */
        WheelLoop(GridTask[] tasks, long startNs, int ticksPerWheel, LongSupplier nanoTime) {
            this.tasks = tasks;
            this.nanoTime = nanoTime;
            this.wheel = new DeadlineTimerWheel(TimeUnit.NANOSECONDS, startNs, 1L << TICK_SHIFT, ticksPerWheel);
            this.taskOfTimer = new Long2LongHashMap(2 * tasks.length, Hashing.DEFAULT_LOAD_FACTOR, NO_TASK);
            for (int i = 0; i < tasks.length; i++) {
                schedule(i);
            }
        }

        /**
         * Polls the wheel once at the current time.
         *
         * @return how long to park before the next pass, ns: until the end of the current tick
         *     if the poll expired nothing, else 0 (poll again at once)
         */
        long pollOnce() {
            if (wheel.poll(nanoTime.getAsLong(), this, Integer.MAX_VALUE) > 0) {
                return 0;
            }
            return Math.max(0, wheel.currentTickTime() - nanoTime.getAsLong());
        }

        @Override
        public boolean onTimerExpiry(TimeUnit timeUnit, long now, long timerId) {
            int task = (int) taskOfTimer.remove(timerId);
            tasks[task].run();
            schedule(task);
            return true;
        }

        private void schedule(int task) {
            taskOfTimer.put(wheel.scheduleTimer(tasks[task].releaseNs()), task);
        }
    }
}
