package io.rtaware.record;

import io.rtaware.core.data.StateValue;
import io.rtaware.core.monitor.CycleOutcome;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.MonitorListener;
import io.rtaware.core.monitor.PeriodChange;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.task.ErrorPolicy;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * Connects a {@link RunRecorder} to a monitor: every committed value, every cycle record, every
 * skipped release and every monitor event is handed to the recorder on the thread that reports
 * it. Allocates nothing.
 */
public final class RecordingListener implements MonitorListener {

    private final RunRecorder recorder;

    private RecordingListener(RunRecorder recorder) {
        this.recorder = recorder;
    }

    /**
     * Creates the recording of a monitor's run (every key, every task, and each task's health on
     * {@code /diagnostics} once a second) and adds it as a listener.
     * Log times become Unix-epoch ns: the wall clock now plus the world time since now
     * ({@link RecordingPlan#logTimeOffsetNs}), both kept in the metadata.
     *
     * @param monitor a monitor that has not started yet
     * @param file the MCAP file, or null to record for the plan's {@link RecordingPlan#tap} alone (a
     *     live server without a file)
     * @param plan topics, metadata, sizes
     * @return the recorder; call {@link RunRecorder#finish()} once the monitor has stopped
     * @throws IOException if the file cannot be written
     */
    public static RunRecorder attach(Monitor monitor, Path file, RecordingPlan plan) throws IOException {
        plan.startingNow(monitor.clock().nanos()).health(monitor);
        List<String> names = monitor.tasks().stream().map(TaskInfo::name).toList();
        List<List<String>> inputs = monitor.tasks().stream().map(TaskInfo::inputKeys).toList();
        RunRecorder recorder = new RunRecorder(file, names, inputs, monitor.keys(), plan);
        monitor.addListener(new RecordingListener(recorder));
        return recorder;
    }

    @Override
    public void onCommitValue(TaskInfo producer, int keyIndex, long generation, long nowNs, StateValue<?> value) {
        recorder.commit(keyIndex, generation, nowNs, value);
    }

    @Override
    public void onCycleRecord(TaskInfo task, CycleOutcome outcome, long releaseNs, long startNs, long endNs,
                              long[] inputGenerations) {
        byte code = switch (outcome) {
            case OK -> RunRecorder.OK;
            case MISS -> RunRecorder.MISS;
            case STALE -> RunRecorder.STALE;
            case ERROR -> RunRecorder.ERROR;
        };
        recorder.cycle(task.index(), code, releaseNs, startNs, endNs, 0, inputGenerations);
    }

    @Override
    public void onSkippedReleases(TaskInfo task, long skipped, long nowNs) {
        recorder.cycle(task.index(), RunRecorder.SKIPPED, nowNs, nowNs, nowNs, skipped, null);
    }

    @Override
    public void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedNs, boolean stillRunning) {
        recorder.event(RunRecorder.DEADLINE_MISS, task.index(), detectedNs, releaseNs, deadlineNs, stillRunning,
                null, null);
    }

    @Override
    public void onExpiredInput(TaskInfo task, String key, long ageNs, long maxAgeNs, long nowNs) {
        recorder.event(RunRecorder.EXPIRED_READ, task.index(), nowNs, ageNs, maxAgeNs, false, key, null);
    }

    @Override
    public void onPeriodChange(TaskInfo task, PeriodChange change, long nowNs) {
        recorder.event(RunRecorder.PERIOD_CHANGE, task.index(), nowNs, change.fromPeriodNs(), change.toPeriodNs(),
                false, null, change.reason());
    }

    @Override
    public void onTaskError(TaskInfo task, Throwable error, ErrorPolicy policy, long nowNs) {
        recorder.event(RunRecorder.TASK_ERROR, task.index(), nowNs, 0, 0, false, null, error);
    }
}
