package io.rtaware.core.monitor;

/**
 * The text of errors and faults on paths a cycle does not take, built here rather than in the
 * classes whose code runs every release.
 *
 * <p>Why: before HotSpot compiles a method with C2 it resolves every string constant of the
 * method's class that is not resolved yet, on the thread whose call or loop asked for the compile
 * ({@code CompileBroker::compile_method}, which calls {@code resolve_string_constants}). A
 * message literal, or the recipe of a string concatenation, on a path no cycle has taken is such a
 * constant; when a worker, a task's thread, the watchdog or the pool's statistics recorder then
 * asks, in steady state, for one of its class's methods to be compiled, it allocates the strings:
 * 96 bytes (a {@code String} and its {@code byte[]}) on a pool worker in about one run of the
 * Epsilon guard in eight, caught with {@code scripts/alloc-probe.c} at the back-edge of the
 * worker's loop just as the loop was queued for C2 (the fatal-error message of
 * {@link PooledExecutor}'s worker). {@code ReleasePathConstantsTest} keeps the classes of the
 * release path free of such constants.
 */
final class OffPathText {

    private OffPathText() {
    }

    /** @return the fault source of an executor's own fault around a task's cycle */
    static String executorCycle(String task) {
        return "executor, cycle of task '" + task + "'";
    }

    /** @return the fault source of a fatal VM error on a pool worker */
    static String poolWorkerFatal(int worker) {
        return "pool worker " + worker + " (fatal VM error: stopping every task)";
    }

    /** @return the fault source of a thread setup that failed on a pool worker */
    static String poolWorkerSetup(int worker) {
        return "thread setup of pool worker " + worker;
    }

    /** @return the fault source of the thread setup of a watchdog */
    static String watchdogSetup(String watchdog) {
        return "thread setup of the " + watchdog;
    }

    /** @return the fault source of a fatal VM error on a task's own thread */
    static String taskThreadFatal(String task) {
        return "task '" + task + "' (fatal VM error: stopping every task)";
    }

    /** @return the fault source of a thread setup that failed on a task's own thread */
    static String taskThreadSetup(String task) {
        return "thread setup of task '" + task + "'";
    }

    /** @return the fault of a thread that did not return after being asked to stop */
    static IllegalStateException didNotStop(Thread thread, long timeoutMs) {
        return new IllegalStateException(thread.getName() + " did not return within " + timeoutMs
                + " ms of stop; interrupting it");
    }

    /** @return the fault source of {@link #didNotStop} */
    static String stopping() {
        return "stop";
    }

    /** @return why a task cannot be released by hand: it is not continuous */
    static String notContinuous(String task, Object kind) {
        return "task '" + task + "' is " + kind + ": only a continuous task can be released by hand";
    }

    /** @return why a task cannot be released by hand: it will not run again */
    static String willNotRunAgain(String task, Object state) {
        return "task '" + task + "' is " + state + " and will not run again";
    }

    /** @return why a statistics table cannot be made */
    static String tableOfTasks(int size) {
        return "a table of " + size + " tasks";
    }

    /** @return why a statistics recorder cannot be made: no task */
    static String recorderForNoTask() {
        return "a statistics recorder for no task";
    }

    /** @return why a statistics recorder cannot be made: tasks of two monitors */
    static String notOfOneMonitor(String task, String first) {
        return "task '" + task + "' is not of the same monitor as '" + first + "'";
    }

    /** @return the fault source of the pool's statistics recorder */
    static String statisticsRecorder() {
        return "the pool's statistics recorder (each cycle records its task's values once "
                + StatisticsTable.RECORD_WHEN_WAITING + " wait)";
    }

    /** @return the fault source of the console reporter's printer thread */
    static String consoleReporter() {
        return "console reporter";
    }
}
