package io.rtaware.core.monitor;

import io.rtaware.core.time.Clock;
import java.util.Collection;

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
 * <p>The executors: {@link ThreadedExecutor} (one platform thread per task, parking on the
 * clock, plus a {@link Watchdog} thread), {@link PooledExecutor} (a few workers taking periodic
 * tasks from one timer structure in deadline order, handing a task from one worker to the next
 * through the timer's lock, since a runtime's cycle state is written by whichever thread ran its
 * previous cycle; plus a watchdog) and {@link StepExecutor} (one test thread advancing a
 * {@code ManualClock}, earliest due release first).
 */
interface Executor {

    /**
     * Runs the release that is due, as every executor does: the task's and the listeners' faults
     * are the runtime's to contain; a fault of the executor's own around the cycle (a framework
     * bug) is reported to {@code faults} and the task is released again by the rules of a cycle
     * that threw ({@link TaskRuntime#recoverAfterFault}). Only a {@link VirtualMachineError}
     * escapes.
     *
     * @param runtime the task whose release is due
     * @param clock world time
     * @param faults where an executor fault goes
     */
    static void runCycle(TaskRuntime runtime, Clock clock, FrameworkFaults faults) {
        try {
            runtime.runCycle();
        } catch (VirtualMachineError fatal) {
            throw fatal;
        } catch (Throwable fault) {
            faults.report(OffPathText.executorCycle(runtime.name()), fault);
            runtime.recoverAfterFault(clock.nanos());
        }
    }

    /**
     * Starts the tasks.
     *
     * @return the start instant: release k of a periodic task is at start + offset + k * period
     */
    long start();

    /**
     * Stops releasing tasks and wakes the threads that wait, without waiting for them: a release
     * already taken may still run, then each thread returns. The first step of a stop.
     */
    void stopReleasing();

    /**
     * After {@link #stopReleasing()}: waits until no thread runs a cycle of {@code tasks} any
     * more (the threads that run them have returned); the other tasks may still be running their
     * last cycle. For the tasks that stop first ({@link io.rtaware.core.task.Task#stopsFirst()}).
     *
     * @param tasks some of the executor's tasks
     */
    void joinThreadsOf(Collection<TaskRuntime> tasks);

    /**
     * @param thread a thread
     * @return true if it is one of the threads that run the tasks' cycles (a cycle that stops
     *     the monitor must not wait for its own thread to return)
     */
    boolean runsCyclesOn(Thread thread);

    /** Stops releasing tasks and waits for every task thread to return. */
    void stopAndJoin();
}
