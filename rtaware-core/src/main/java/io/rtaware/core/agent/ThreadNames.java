package io.rtaware.core.agent;

/**
 * The names of rtaware's own threads that something outside the thread's module looks for, in
 * one place: the task threads, pool workers, watchdog and the pool's statistics recorder, which
 * make up the per-release path whose allocation {@link io.rtaware.core.testing.ThreadAllocation#ofFrameworkThreads()} counts
 * and the bench watches, and the observers off that path, which it leaves out (the console
 * printer, the stop helpers, the recorder's writer in rtaware-record, the live view's
 * publisher and HTTP threads in rtaware-live). Each thread is named from here, so a rename cannot split a thread
 * from the rule that knows it.
 */
public final class ThreadNames {

    /** The prefix of every thread the framework names ({@code rtaware-t3}, {@code rtaware-monitor}, ...). */
    public static final String PREFIX = "rtaware-";
    /** The monitor's watchdog, which reports misses at their deadlines. */
    public static final String WATCHDOG = PREFIX + "monitor";
    /** The pool workers' prefix, followed by the worker's number from 0. */
    public static final String POOL_WORKER_PREFIX = PREFIX + "pool-";
    /** The pool's statistics recorder, which records the pooled tasks' values into their histograms. */
    public static final String STATISTICS = PREFIX + "statistics";
    /** The console reporter's printer. */
    public static final String CONSOLE = PREFIX + "console";
    /** The shutdown hook that stops a monitor when the JVM exits. */
    public static final String SHUTDOWN = PREFIX + "shutdown";
    /** The helper thread that stops a monitor when a task asks it to. */
    public static final String STOP = PREFIX + "stop";
    /** The recorder's writer (rtaware-record), which encodes and writes what the task threads handed over. */
    public static final String RECORDER = PREFIX + "recorder";
    /** The live view's publisher (rtaware-live), which builds the snapshots a browser is sent. */
    public static final String LIVE_PUBLISHER = PREFIX + "live-publisher";
    /** The live view's HTTP threads' prefix (rtaware-live), followed by a number from 1: they serve the browser. */
    public static final String LIVE_HTTP_PREFIX = PREFIX + "live-http-";

    private ThreadNames() {
    }

    /**
     * @param taskName the task's name
     * @return the name of the task's thread on the thread-per-task executor
     */
    public static String task(String taskName) {
        return PREFIX + taskName;
    }

    /**
     * @param worker the worker's number, from 0
     * @return the name of that pool worker
     */
    public static String poolWorker(int worker) {
        return POOL_WORKER_PREFIX + worker;
    }
}
