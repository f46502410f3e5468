package io.rtaware.bench.compare;

import io.netty.util.HashedWheelTimer;
import io.netty.util.Timeout;
import io.netty.util.Timer;
import io.netty.util.TimerTask;
import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.LongSupplier;

/**
 * The hashed timer wheel a Java developer would pick for many timers ({@code netty-wheel}):
 * Netty's {@link HashedWheelTimer} with its tick set to {@value #TICK_MS} ms, as a user timing
 * periodic tasks of a few milliseconds would set it (Netty's default, 100 ms, is meant for I/O
 * timeouts), and its default wheel of {@value #TICKS_PER_WHEEL} ticks (a 10 ms period
 * sits in the first fiftieth of the wheel, so no timer waits out a round). Its one worker thread
 * wakes every tick (a {@code Thread.sleep} rounded up to whole milliseconds), expires the
 * timeouts of the tick and runs their tasks itself, as a {@link TimerTask} runs unless its user
 * hands it to an executor. A periodic task is a timeout that re-arms itself with
 * {@link Timer#newTimeout} from its own run, at its next grid point ({@link GridTask}); its
 * lateness is that run's start against the grid point. Each re-arm allocates Netty's timeout
 * object, which the row's bytes per release show.
 */
final class NettyWheelSegment implements SegmentExecutor {

    /** The wheel's tick, ms. */
    static final long TICK_MS = 1;
    /** Netty's default wheel size. */
    static final int TICKS_PER_WHEEL = 512;
    private static final String THREAD = "netty-wheel";

    private final BusyWork work;
    private HashedWheelTimer timer;
    private Thread worker;
    private volatile boolean running;

    /** @param work the calibrated busy loop */
    NettyWheelSegment(BusyWork work) {
        this.work = work;
    }

    @Override
    public String name() {
        return "netty-wheel";
    }

    @Override
    public void start(List<BenchSpec> specs, List<ReleaseStats> stats) {
        timer = new HashedWheelTimer(r -> {
            worker = new Thread(r, THREAD);
            worker.setDaemon(true);
            return worker;
        }, TICK_MS, TimeUnit.MILLISECONDS, TICKS_PER_WHEEL);
        timer.start();
        running = true;
        long t0 = System.nanoTime();
        for (GridTask task : GridTask.of(specs, stats, t0, work)) {
            new Rearming(task, timer, () -> running, System::nanoTime).arm();
        }
    }

    @Override
    public long[] helperThreadIds() {
        return new long[] {worker.getId()};
    }

    @Override
    public void stop() {
        running = false;
        timer.stop(); // interrupts the worker and joins it
    }

    /** One periodic task: a timer task that runs the release due and arms a timeout for the next. */
    static final class Rearming implements TimerTask {
        private final GridTask task;
        private final Timer timer;
        private final BooleanSupplier running;
        private final LongSupplier nanoTime;

        /**
         * @param task the task and its grid
         * @param timer the wheel
         * @param running whether to re-arm after a run
         * @param nanoTime the clock the delay to the next release is taken from
         */
        Rearming(GridTask task, Timer timer, BooleanSupplier running, LongSupplier nanoTime) {
            this.task = task;
            this.timer = timer;
            this.running = running;
            this.nanoTime = nanoTime;
        }

        /** Arms the timeout of the task's next release. */
        void arm() {
            timer.newTimeout(this, task.releaseNs() - nanoTime.getAsLong(), TimeUnit.NANOSECONDS);
        }

        @Override
        public void run(Timeout timeout) {
            task.run();
            if (running.getAsBoolean()) {
                try {
                    arm();
                } catch (IllegalStateException stoppedMeanwhile) {
                    // stop() ran between the check and the re-arm: the segment is over
                }
            }
        }
    }
}
