package io.rtaware.core.monitor;

/**
 * How task cycles get onto threads: the seam between the rules and the waiting.
 *
 * <p>An executor owns no timing rule. For every task it repeats, on whichever thread it chooses:
 * <pre>{@code
 * long due = runtime.nextReleaseNs();          // the rulebook says when (world time)
 * if (due == TaskRuntime.NEVER) stop driving this task;
 * wait until clock.nanos() >= due;             // the executor's only job: how to wait
 * runtime.runCycle();                          // the rulebook runs and accounts the cycle
 * }</pre>
 * and it calls {@link TaskRuntime#checkDeadline(long)} on running periodic tasks so misses are
 * reported at the deadline (a watchdog thread, or the manual clock's advance observer). Before
 * the first release it calls {@link TaskRuntime#begin(long, Runnable, long)} on every task with
 * one start instant, how to stop the monitor from a cycle (STOP_ALL), and its spacing for
 * zero-duration continuous cycles. A fault of its own around {@code runCycle} is reported to the
 * monitor's {@link FrameworkErrorHandler} and followed by {@link TaskRuntime#recoverAfterFault}.
 *
 * <p>The two executors today: {@link ThreadedExecutor} (one platform thread per task, parking on
 * the clock, plus a watchdog thread) and {@link StepExecutor} (one test thread advancing a
 * {@code ManualClock}, earliest due release first). A pooled executor (a few workers taking
 * periodic tasks from one timer structure in deadline order) fits the same loop: its timer
 * orders tasks by {@code nextReleaseNs()}, and a worker hands a task to the next with a
 * happens-before edge (the timer's lock or queue), since a runtime's cycle state is written by
 * whichever thread ran its previous cycle.
 */
interface Executor {

    /**
     * Starts the tasks.
     *
     * @return the start instant: release k of a periodic task is at start + offset + k * period
     */
    long start();

    /** Stops releasing tasks and waits for every task thread to return. */
    void stopAndJoin();
}
