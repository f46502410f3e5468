package io.rtaware.core.monitor;

import io.rtaware.core.task.ErrorPolicy;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** Records every event as a line, for exact assertions. Thread-safe. */
final class RecordingListener implements MonitorListener {

    /** One deadline miss as reported. */
    record Miss(String task, long releaseNs, long deadlineNs, long detectedNs, boolean stillRunning) {
    }

    final List<Miss> misses = Collections.synchronizedList(new ArrayList<>());
    final List<String> events = Collections.synchronizedList(new ArrayList<>());
    final List<Throwable> errors = Collections.synchronizedList(new ArrayList<>());

    @Override
    public void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedNs, boolean stillRunning) {
        misses.add(new Miss(task.name(), releaseNs, deadlineNs, detectedNs, stillRunning));
        events.add("miss " + task.name() + " release=" + releaseNs + " detected=" + detectedNs + " running=" + stillRunning);
    }

    @Override
    public void onSkippedReleases(TaskInfo task, long skipped, long nowNs) {
        events.add("skipped " + task.name() + " " + skipped + " at=" + nowNs);
    }

    @Override
    public void onStaleRun(TaskInfo task, long nowNs) {
        events.add("stale " + task.name() + " at=" + nowNs);
    }

    @Override
    public void onExpiredInput(TaskInfo task, String key, long ageNs, long maxAgeNs, long nowNs) {
        events.add("expired " + task.name() + " " + key + " age=" + ageNs + " max=" + maxAgeNs + " at=" + nowNs);
    }

    @Override
    public void onTaskError(TaskInfo task, Throwable error, ErrorPolicy policy, long nowNs) {
        errors.add(error);
        events.add("error " + task.name() + " " + policy + " at=" + nowNs);
    }

    @Override
    public void onStateChange(TaskInfo task, TaskState state, long nowNs) {
        events.add("state " + task.name() + " " + state + " at=" + nowNs);
    }

    long count(String prefix) {
        synchronized (events) {
            return events.stream().filter(e -> e.startsWith(prefix)).count();
        }
    }
}
