package io.rtaware.replay;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.monitor.MonitorListener;
import io.rtaware.core.monitor.TaskDeclaration;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.testing.TaskHarness;
import io.rtaware.core.time.ManualClock;
import io.rtaware.record.TaskCycleMessage;
import java.io.IOException;
import java.util.List;
import java.util.function.Supplier;
import org.HdrHistogram.Histogram;

/**
 * Exact re-execution of recorded cycles. For one task of the controller: a fresh instance of it
 * runs under a {@link TaskHarness} (the real handles and store, the step executor, a
 * {@link ManualClock}); its recorded cycles are replayed in order in that one instance, so its
 * state (the planner's map, the waypoint index) evolves as it did. Before each cycle, every input
 * whose recorded generation differs from the one fed before is committed with its recorded value
 * at its recorded commit time (so the task sees NEW and OLD, and the same ages, as in the run);
 * the cycle then runs at its recorded start time, and each output it commits is compared with
 * the commit the recording has from the same cycle (the commit at the cycle's end time).
 *
 * <p>A commit time the manual clock cannot reproduce (a value committed, on another thread, after
 * an earlier cycle of this task had read the clock, or after this cycle's start) is committed at
 * the nearest time it can be: only that input's age differs, by the width of the race.
 *
 * <p>A cycle whose input value, own record or output commit the recorder dropped cannot be
 * replayed exactly, nor can any later cycle of the task (its state no longer follows the run's):
 * such cycles are counted as not replayable, and the first is named, instead of reporting a
 * difference that would be the recorder's. Skipped releases count as cycles by their records and
 * are identical (nothing ran in the run, nothing runs here). Not thread-safe.
 */
public final class ExactReplay {

    private static final long HIGHEST_NS = 3_600_000_000_000L;

    private ExactReplay() {
    }

    /**
     * Where a replayed cycle first differed from the recording.
     *
     * @param cycle the cycle's record number in the task's timing channel (from 0)
     * @param releaseNs its release, world ns
     * @param key the output key that differed ({@code (cycle)} if the cycle threw in one and not the other)
     * @param field the field, with the index for an array element ({@code (commit)}: committed in one only)
     * @param recorded the recorded value
     * @param replayed the replayed value
     */
    public record Difference(long cycle, long releaseNs, String key, String field, String recorded, String replayed) {
    }

    /**
     * The first cycle that could not be replayed exactly.
     *
     * @param cycle its record number
     * @param reason why
     */
    public record NotReplayable(long cycle, String reason) {
    }

    /**
     * One task's replay.
     *
     * @param name the task
     * @param cycles timing records replayed (cycles and runs of skipped releases)
     * @param identical cycles whose outputs were identical
     * @param different cycles whose outputs differed
     * @param firstDifference the first difference, or null
     * @param notReplayable cycles that could not be replayed exactly (recorder drops)
     * @param firstNotReplayable the first of them, or null
     * @param inputsMoved input values committed at another time than recorded, because the manual
     *     clock had passed it or it lay after the cycle's start (a race in the run): their age differs
     * @param execNs execution time of each replayed cycle on this machine (wall ns)
     */
    public record TaskResult(String name, long cycles, long identical, long different, Difference firstDifference,
                             long notReplayable, NotReplayable firstNotReplayable, long inputsMoved,
                             Histogram execNs) {
    }

    /**
     * Replays one task's recorded cycles.
     *
     * @param recording the recording
     * @param controller makes a fresh set of the controller's tasks (called twice)
     * @param task the task's name
     * @return the result
     * @throws IOException if the recording lacks what the task needs or a value in it is malformed
     */
    public static TaskResult replay(Recording recording, Supplier<List<TaskSpec>> controller, String task)
            throws IOException {
        TaskDeclaration declared = TaskDeclaration.of(find(controller.get(), task));
        TaskSpec spec = find(controller.get(), task);
        Recording.TaskTimeline timeline = recording.tasks().get(task);
        List<String> inputNames = declared.inputs().stream().map(in -> in.key().name()).toList();
        if (!inputNames.equals(timeline.inputs())) {
            throw new IOException("task '" + task + "' reads " + inputNames + " but its recorded cycles read "
                    + timeline.inputs() + ": the recording was made by another controller");
        }
        return new Run(recording, declared, spec, timeline).replay();
    }

    private static TaskSpec find(List<TaskSpec> specs, String task) {
        for (TaskSpec s : specs) {
            if (s.name().equals(task)) {
                return s;
            }
        }
        throw new IllegalArgumentException("the controller has no task '" + task + "'");
    }

    /** One task's replay in progress. */
    private static final class Run {
        final Recording recording;
        final TaskSpec spec;
        final Recording.TaskTimeline timeline;
        final Port<?>[] inputs;
        final Port<?>[] outputs;
        final TaskHarness harness;
        /** The task's outputs by the harness's key index, for the commit listener. */
        Port<?>[] outputByKey = new Port<?>[0];
        final Histogram execNs = new Histogram(1, HIGHEST_NS, 3);
        final Port<?>[] due;
        long cycles;
        long identical;
        long different;
        Difference first;
        long notReplayable;
        NotReplayable firstNotReplayable;
        long inputsMoved;

        Run(Recording recording, TaskDeclaration declared, TaskSpec spec, Recording.TaskTimeline timeline)
                throws IOException {
            this.recording = recording;
            this.spec = spec;
            this.timeline = timeline;
            inputs = new Port<?>[declared.inputs().size()];
            long startNs = 0;
            for (int i = 0; i < inputs.length; i++) {
                inputs[i] = port(declared.inputs().get(i).key(), true);
                List<Recording.Commit> commits = inputs[i].channel.commits();
                if (!commits.isEmpty()) {
                    startNs = Math.min(startNs, commits.get(0).timeNs());
                }
            }
            outputs = new Port<?>[declared.outputs().size()];
            for (int i = 0; i < outputs.length; i++) {
                outputs[i] = port(declared.outputs().get(i), false);
            }
            due = new Port<?>[inputs.length];
            if (!timeline.cycles().isEmpty()) {
                startNs = Math.min(startNs, timeline.cycles().get(0).message().releaseNs());
            }
            TaskHarness.Builder builder = TaskHarness.builder(new ManualClock(startNs));
            for (Port<?> in : inputs) {
                builder.input(in.codec.key());
            }
            harness = builder.task(spec.name(), spec.task()).listener(new MonitorListener() {
                @Override
                public void onCommitValue(TaskInfo producer, int keyIndex, long generation, long nowNs,
                                          StateValue<?> value) {
                    Port<?> out = keyIndex < outputByKey.length ? outputByKey[keyIndex] : null;
                    if (out != null) {
                        out.committed(generation, value);
                    }
                }
            }).build();
            List<Key<?>> all = harness.monitor().keys();
            outputByKey = new Port<?>[all.size()];
            for (Port<?> out : outputs) {
                outputByKey[all.indexOf(out.codec.key())] = out;
            }
        }

        private <T extends StateValue<T>> Port<T> port(Key<T> key, boolean input) throws IOException {
            Recording.KeyChannel channel = recording.keys().get(key.name());
            if (channel == null && input) {
                throw new IOException("the recording has no channel of key '" + key.name() + "', which task '"
                        + spec.name() + "' reads");
            }
            return new Port<>(new ValueCodec<>(key), channel);
        }

        TaskResult replay() throws IOException {
            long expected = 0;
            for (Recording.Cycle c : timeline.cycles()) {
                cycles++;
                TaskCycleMessage m = c.message();
                if (firstNotReplayable == null && c.number() != expected) {
                    notReplayable(c.number(), "the recorder dropped cycle record " + expected);
                }
                expected = c.number() + 1;
                if (firstNotReplayable != null) {
                    notReplayable++;
                    continue;
                }
                if (m.outcome().equals("skipped")) {
                    identical++;
                    continue;
                }
                String missing = feedInputs(m);
                if (missing != null) {
                    notReplayable(c.number(), missing);
                    notReplayable++;
                    continue;
                }
                long wallStart = System.nanoTime();
                Throwable error = harness.cycle(spec.name(), Math.max(m.startNs(), harness.nowNs()));
                execNs.recordValue(Math.min(HIGHEST_NS, Math.max(1, System.nanoTime() - wallStart)));
                Difference d = compareOutputs(c.number(), m, error);
                if (firstNotReplayable != null) {
                    notReplayable++;
                } else if (d == null) {
                    identical++;
                } else {
                    different++;
                    if (first == null) {
                        first = d;
                    }
                }
            }
            harness.stop();
            return new TaskResult(spec.name(), cycles, identical, different, first, notReplayable,
                    firstNotReplayable, inputsMoved, execNs);
        }

        private void notReplayable(long cycle, String reason) {
            if (firstNotReplayable == null) {
                firstNotReplayable = new NotReplayable(cycle, reason);
            }
        }

        /** Commits every input whose generation changed, in commit-time order; the reason if one was dropped. */
        private String feedInputs(TaskCycleMessage m) throws IOException {
            long[] generations = m.inputGenerations();
            int n = 0;
            for (int i = 0; i < inputs.length; i++) {
                Port<?> in = inputs[i];
                long g = generations[i];
                if (g == 0 || g == in.fedGeneration) {
                    continue;
                }
                Recording.Commit commit = in.channel.generation(g);
                if (commit == null || g < in.fedGeneration) {
                    return "the recorder dropped generation " + g + " of input '" + in.codec.key().name() + "'";
                }
                in.pending = commit;
                in.fedGeneration = g;
                int k = n++;
                while (k > 0 && due[k - 1].pending.timeNs() > commit.timeNs()) {
                    due[k] = due[k - 1];
                    k--;
                }
                due[k] = in;
            }
            for (int i = 0; i < n; i++) {
                Port<?> in = due[i];
                long atNs = Math.min(Math.max(in.pending.timeNs(), harness.nowNs()), Math.max(m.startNs(), harness.nowNs()));
                if (atNs != in.pending.timeNs()) {
                    inputsMoved++;
                }
                in.publish(harness, atNs);
                due[i] = null;
            }
            return null;
        }

        private Difference compareOutputs(long cycle, TaskCycleMessage m, Throwable error) throws IOException {
            Difference d = null;
            boolean recordedError = m.outcome().equals("error");
            if (recordedError != (error != null)) {
                d = new Difference(cycle, m.releaseNs(), "(cycle)", "threw", recordedError ? "threw" : "returned",
                        error != null ? error.toString() : "returned");
            }
            for (Port<?> out : outputs) {
                long g = out.committedGeneration;
                boolean replayCommitted = g != out.replayGeneration;
                out.replayGeneration = g;
                if (out.channel == null) {
                    continue;
                }
                Recording.Commit next = out.channel.generation(out.fedGeneration + 1);
                if (next == null && hasLater(out.channel, out.fedGeneration + 1)) {
                    notReplayable(cycle, "the recorder dropped generation " + (out.fedGeneration + 1) + " of output '"
                            + out.codec.key().name() + "'");
                    return null;
                }
                boolean recordedCommitted = next != null && next.timeNs() == m.endNs();
                if (recordedCommitted) {
                    out.fedGeneration++;
                }
                if (d != null) {
                    continue;
                }
                if (recordedCommitted != replayCommitted) {
                    d = new Difference(cycle, m.releaseNs(), out.codec.key().name(), "(commit)",
                            recordedCommitted ? "committed" : "no commit", replayCommitted ? "committed" : "no commit");
                } else if (recordedCommitted) {
                    d = out.compare(next, cycle, m.releaseNs());
                }
            }
            return d;
        }

        private static boolean hasLater(Recording.KeyChannel channel, long generation) {
            List<Recording.Commit> commits = channel.commits();
            return !commits.isEmpty() && commits.get(commits.size() - 1).generation() > generation;
        }
    }

    /** One key of the task under replay: its codec, recorded channel, a buffer, and the generations seen. */
    private static final class Port<T extends StateValue<T>> {
        final ValueCodec<T> codec;
        final Recording.KeyChannel channel;
        final T buffer;
        /** Inputs: the recorded generation last committed into the harness; outputs: the last matched. */
        long fedGeneration;
        /** Outputs: the harness's generation after the last cycle. */
        long replayGeneration;
        /** Outputs: the generation of the replayed task's last commit. */
        long committedGeneration;
        Recording.Commit pending;

        Port(ValueCodec<T> codec, Recording.KeyChannel channel) {
            this.codec = codec;
            this.channel = channel;
            this.buffer = codec.key().newBuffer();
        }

        void publish(TaskHarness harness, long atNs) throws IOException {
            codec.decode(pending, buffer);
            harness.publish(codec.key(), buffer, atNs);
            pending = null;
        }

        /** Outputs: the replayed task's newest commit, copied here when it commits. */
        @SuppressWarnings("unchecked")
        void committed(long generation, StateValue<?> value) {
            buffer.copyFrom((T) value);
            committedGeneration = generation;
        }

        /** Compares the value last {@link #committed} with a recorded commit. */
        Difference compare(Recording.Commit recorded, long cycle, long releaseNs) throws IOException {
            if (codec.sameAs(buffer, recorded)) {
                return null;
            }
            ValueCodec.Difference d = codec.difference(buffer, recorded);
            return new Difference(cycle, releaseNs, codec.key().name(), d.field(), d.recorded(), d.replayed());
        }
    }
}
