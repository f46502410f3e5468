package io.rtaware.core.monitor;

/**
 * Receives every fault on the framework's side of a run: a {@link MonitorListener} (or the
 * trace recorder) that threw, a termination handler that threw, a thread setup that failed, or
 * an unexpected error in an executor. The monitor catches each of them (any
 * {@link Throwable}, as an Agrona {@code AgentRunner} does), counts it in the report
 * ({@code listener_errors} per task, {@code framework_errors} in total) and hands it here; the
 * task threads and the watchdog go on. Faults of a task's own cycle are not framework faults:
 * they are the task's {@code errors} and follow its {@link io.rtaware.core.task.ErrorPolicy}.
 *
 * <p>Called on the thread where the fault happened (a task thread, the watchdog, the stopping
 * thread), possibly concurrently: implementations must be thread-safe and must not block. The
 * default is {@link RateLimitedErrorPrinter} on standard error.
 */
@FunctionalInterface
public interface FrameworkErrorHandler {

    /**
     * @param source where it happened, e.g. {@code listener TraceRecorder.onCycle on task 'tick'}
     * @param error what was thrown
     */
    void onError(String source, Throwable error);
}
