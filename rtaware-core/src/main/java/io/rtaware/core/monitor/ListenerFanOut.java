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

    private final FrameworkFaults faults;
    private MonitorListener[] listeners = new MonitorListener[0];

    ListenerFanOut(FrameworkFaults faults) {
        this.faults = faults;
    }

    /** Sets the listeners; only before the tasks start. */
    void listeners(MonitorListener[] all) {
        this.listeners = all;
    }

    private void contain(TaskRuntime task, MonitorListener listener, String event, Throwable error) {
        task.statistics().listenerError();
        faults.report("listener " + listener.getClass().getName() + "." + event + " on task '" + task.name() + "'",
                error);
    }

    void onDeadlineMiss(TaskRuntime task, long releaseNs, long deadlineNs, long detectedNs, boolean stillRunning) {
        for (MonitorListener l : listeners) {
            try {
                l.onDeadlineMiss(task, releaseNs, deadlineNs, detectedNs, stillRunning);
            } catch (Throwable t) {
                contain(task, l, "onDeadlineMiss", t);
            }
        }
    }

    void onSkippedReleases(TaskRuntime task, long skipped, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onSkippedReleases(task, skipped, nowNs);
            } catch (Throwable t) {
                contain(task, l, "onSkippedReleases", t);
            }
        }
    }

    void onStaleRun(TaskRuntime task, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onStaleRun(task, nowNs);
            } catch (Throwable t) {
                contain(task, l, "onStaleRun", t);
            }
        }
    }

    void onExpiredInput(TaskRuntime task, String key, long ageNs, long maxAgeNs, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onExpiredInput(task, key, ageNs, maxAgeNs, nowNs);
            } catch (Throwable t) {
                contain(task, l, "onExpiredInput", t);
            }
        }
    }

    void onTaskError(TaskRuntime task, Throwable error, ErrorPolicy policy, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onTaskError(task, error, policy, nowNs);
            } catch (Throwable t) {
                contain(task, l, "onTaskError", t);
            }
        }
    }

    void onStateChange(TaskRuntime task, TaskState state, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onStateChange(task, state, nowNs);
            } catch (Throwable t) {
                contain(task, l, "onStateChange", t);
            }
        }
    }

    void onCycle(TaskRuntime task, long releaseNs, long startNs, long endNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onCycle(task, releaseNs, startNs, endNs);
            } catch (Throwable t) {
                contain(task, l, "onCycle", t);
            }
        }
    }

    void onCommit(TaskRuntime task, int keyIndex, long generation, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onCommit(task, keyIndex, generation, nowNs);
            } catch (Throwable t) {
                contain(task, l, "onCommit", t);
            }
        }
    }

    void onCommitValue(TaskRuntime task, int keyIndex, long generation, long nowNs,
                       io.rtaware.core.data.StateValue<?> value) {
        for (MonitorListener l : listeners) {
            try {
                l.onCommitValue(task, keyIndex, generation, nowNs, value);
            } catch (Throwable t) {
                contain(task, l, "onCommitValue", t);
            }
        }
    }

    void onCycleRecord(TaskRuntime task, CycleOutcome outcome, long releaseNs, long startNs, long endNs,
                       long[] inputGenerations) {
        for (MonitorListener l : listeners) {
            try {
                l.onCycleRecord(task, outcome, releaseNs, startNs, endNs, inputGenerations);
            } catch (Throwable t) {
                contain(task, l, "onCycleRecord", t);
            }
        }
    }

    void onPeriodChange(TaskRuntime task, PeriodChange change, long nowNs) {
        for (MonitorListener l : listeners) {
            try {
                l.onPeriodChange(task, change, nowNs);
            } catch (Throwable t) {
                contain(task, l, "onPeriodChange", t);
            }
        }
    }
}
