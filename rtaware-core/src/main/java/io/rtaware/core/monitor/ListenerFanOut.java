package io.rtaware.core.monitor;

import io.rtaware.core.task.ErrorPolicy;

/**
 * Hands each event of the run to every {@link MonitorListener}, containing their faults: a
 * listener that throws is counted on the task whose event it was ({@code listener_errors}) and
 * reported to the {@link FrameworkErrorHandler}, and the next listener, the task's cycle and the
 * watchdog go on as if nothing happened. No allocation unless a listener throws.
 *
 * <p>The listener array is fixed before the tasks start ({@link #listeners(MonitorListener[])});
 * the start of the task threads publishes it. Thread-safe after that.
 */
final class ListenerFanOut {

    /*
     * Listener events by number, their names built once with the class, and the fault message
     * built in FrameworkFaults: no string constant is left in this class's constant pool for a
     * cycle to resolve. A heap dump of a pooled run whose zero-allocation guard failed (288 bytes,
     * about one run in six) showed exactly this class's unresolved constants (the names of events
     * no cycle had reported, and the message's concatenation recipe) interned together late in the
     * run, on a worker thread, just after a JIT deoptimization: before a C2 compile HotSpot resolves
     * every string constant of the method's class on the thread that asked for it (OffPathText);
     * with no constant left it cannot recur.
     */
    private static final int DEADLINE_MISS = 0;
    private static final int SKIPPED_RELEASES = 1;
    private static final int STALE_RUN = 2;
    private static final int EXPIRED_INPUT = 3;
    private static final int TASK_ERROR = 4;
    private static final int STATE_CHANGE = 5;
    private static final int CYCLE = 6;
    private static final int COMMIT = 7;
    private static final int COMMIT_VALUE = 8;
    private static final int CYCLE_RECORD = 9;
    private static final int PERIOD_CHANGE = 10;
    private static final String[] EVENT_NAMES = {
        "onDeadlineMiss", "onSkippedReleases", "onStaleRun", "onExpiredInput", "onTaskError", "onStateChange",
        "onCycle", "onCommit", "onCommitValue", "onCycleRecord", "onPeriodChange"};

    private final FrameworkFaults faults;
    private MonitorListener[] listeners = new MonitorListener[0];

    ListenerFanOut(FrameworkFaults faults) {
        this.faults = faults;
    }

    /** Sets the listeners; only before the tasks start. */
    void listeners(MonitorListener[] all) {
        this.listeners = all;
    }

    private void contain(TaskRuntime task, MonitorListener listener, int event, Throwable error) {
        task.statistics().listenerError();
        faults.reportListenerFault(listener.getClass().getName(), EVENT_NAMES[event], task.name(), error);
    }

    void onDeadlineMiss(TaskRuntime task, long releaseNs, long deadlineNs, long detectedNs, boolean stillRunning) {
        for (MonitorListener l : listeners) {
            try {
                l.onDeadlineMiss(task, releaseNs, deadlineNs, detectedNs, stillRunning);
            } catch (Throwable t) {
                contain(task, l, DEADLINE_MISS, t);
            }
        }
    }

    void onSkippedReleases(TaskRuntime task, long skipped, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onSkippedReleases(task, skipped, nowNs);
            } catch (Throwable t) {
                contain(task, l, SKIPPED_RELEASES, t);
            }
        }
    }

    void onStaleRun(TaskRuntime task, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onStaleRun(task, nowNs);
            } catch (Throwable t) {
                contain(task, l, STALE_RUN, t);
            }
        }
    }

    void onExpiredInput(TaskRuntime task, String key, long ageNs, long maxAgeNs, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onExpiredInput(task, key, ageNs, maxAgeNs, nowNs);
            } catch (Throwable t) {
                contain(task, l, EXPIRED_INPUT, t);
            }
        }
    }

    void onTaskError(TaskRuntime task, Throwable error, ErrorPolicy policy, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onTaskError(task, error, policy, nowNs);
            } catch (Throwable t) {
                contain(task, l, TASK_ERROR, t);
            }
        }
    }

    void onStateChange(TaskRuntime task, TaskState state, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onStateChange(task, state, nowNs);
            } catch (Throwable t) {
                contain(task, l, STATE_CHANGE, t);
            }
        }
    }

    void onCycle(TaskRuntime task, long releaseNs, long startNs, long endNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onCycle(task, releaseNs, startNs, endNs);
            } catch (Throwable t) {
                contain(task, l, CYCLE, t);
            }
        }
    }

    void onCommit(TaskRuntime task, int keyIndex, long generation, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onCommit(task, keyIndex, generation, nowNs);
            } catch (Throwable t) {
                contain(task, l, COMMIT, t);
            }
        }
    }

    void onCommitValue(TaskRuntime task, int keyIndex, long generation, long nowNs,
                       io.rtaware.core.data.StateValue<?> value) {
        for (MonitorListener l : listeners) {
            try {
                l.onCommitValue(task, keyIndex, generation, nowNs, value);
            } catch (Throwable t) {
                contain(task, l, COMMIT_VALUE, t);
            }
        }
    }

    void onCycleRecord(TaskRuntime task, CycleOutcome outcome, long releaseNs, long startNs, long endNs,
                       long[] inputGenerations) {
        for (MonitorListener l : listeners) {
            try {
                l.onCycleRecord(task, outcome, releaseNs, startNs, endNs, inputGenerations);
            } catch (Throwable t) {
                contain(task, l, CYCLE_RECORD, t);
            }
        }
    }

    void onPeriodChange(TaskRuntime task, PeriodChange change, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onPeriodChange(task, change, nowNs);
            } catch (Throwable t) {
                contain(task, l, PERIOD_CHANGE, t);
            }
        }
    }
}
