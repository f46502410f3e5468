package io.rtaware.replay;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.monitor.TaskDeclaration;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import io.rtaware.record.TaskCycleMessage;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * What-if periods, offline: the controller's tasks, with the periods asked for, run on a
 * {@link ManualClock} with the {@link StepExecutor} on the recorded sensor stream. A data task
 * (named as the recording's, e.g. {@code player}) commits every recorded value of the keys the
 * controller reads but does not produce ({@code laser}, {@code odometry}) at its recorded world
 * time; each controller cycle runs the real behavior and is then charged an execution time
 * measured for that task in the recording, the task's recorded execution times in order,
 * starting over when they run out; so misses, skipped releases and stale runs appear as they
 * would have. Open loop: what the controller commands goes nowhere, the sensor stream (the path
 * driven) is the recorded one.
 *
 * <p>The step executor runs one cycle at a time, as on one core: a sensor value due while a
 * cycle is charged its execution time is committed when that cycle ends.
 */
public final class WhatIfReplay {

    private WhatIfReplay() {
    }

    /**
     * What a what-if replay found.
     *
     * @param report the monitor's report, as a run writes it
     * @param dataTask the name of the task that fed the recorded sensor stream (no such task runs
     *     when the controller reads no key it does not produce)
     * @param sensorKeys the keys it fed
     * @param sensorCommits how many values it committed
     */
    public record Result(Report report, String dataTask, List<String> sensorKeys, long sensorCommits) {
    }

    /**
     * @param recording the recording
     * @param controllerTasks a fresh set of the controller's tasks with the periods to try
     * @param probeTasks another fresh set, only to find which keys the tasks read and write
     * @return the report
     * @throws IOException if the recording lacks a sensor key or a value in it is malformed
     */
    public static Result replay(Recording recording, List<TaskSpec> controllerTasks, List<TaskSpec> probeTasks)
            throws IOException {
        Set<String> produced = new LinkedHashSet<>();
        Set<Key<?>> consumed = new LinkedHashSet<>();
        Set<String> controllerNames = new LinkedHashSet<>();
        for (TaskSpec spec : probeTasks) {
            TaskDeclaration declared = TaskDeclaration.of(spec);
            declared.outputs().forEach(k -> produced.add(k.name()));
            declared.inputs().forEach(in -> consumed.add(in.key()));
            controllerNames.add(spec.name());
        }
        List<Feed<?>> feeds = new ArrayList<>();
        Set<String> fed = new LinkedHashSet<>();
        for (Key<?> key : consumed) {
            if (!produced.contains(key.name()) && fed.add(key.name())) {
                Recording.KeyChannel channel = recording.keys().get(key.name());
                if (channel == null) {
                    throw new IOException("the recording has no channel of key '" + key.name()
                            + "', which the controller reads");
                }
                feeds.add(feed(key, channel));
            }
        }
        // The replay starts where the recording does: its first sensor value or first release
        // (world time 0 for a run; a bench's world time is the machine's monotonic clock).
        long startNs = Long.MAX_VALUE;
        long values = 0;
        for (Feed<?> f : feeds) {
            List<Recording.Commit> commits = f.channel.commits();
            values += commits.size();
            if (!commits.isEmpty()) {
                startNs = Math.min(startNs, commits.get(0).timeNs());
            }
        }
        for (Recording.TaskTimeline timeline : recording.tasks().values()) {
            if (!timeline.cycles().isEmpty()) {
                startNs = Math.min(startNs, timeline.cycles().get(0).message().releaseNs());
            }
        }
        startNs = startNs == Long.MAX_VALUE ? 0 : startNs;
        String dataTask = recording.tasks().keySet().stream().filter(t -> !controllerNames.contains(t))
                .findFirst().orElse("player");

        ManualClock clock = new ManualClock(startNs);
        Feed<?>[] fedKeys = feeds.toArray(new Feed<?>[0]); // arrays: iterating them allocates nothing
        Feeder feeder = new Feeder(fedKeys);
        Monitor.Builder builder = Monitor.builder(clock);
        if (fedKeys.length > 0) { // a controller that reads no sensor (a bench's tasks) has no data task
            builder.task(new TaskSpec(dataTask, Schedule.continuous(), ErrorPolicy.CONTINUE, feeder));
        }
        for (TaskSpec spec : controllerTasks) {
            builder.task(new TaskSpec(spec.name(), spec.schedule(), spec.errorPolicy(),
                    new Charged(spec.task(), clock, recordedExecNs(recording, spec.name()))));
        }
        Monitor monitor = builder.build();
        StepExecutor step = monitor.startStepped();
        // Merge the feeds by commit time (ties: feed order); every feed due at a time goes in one cycle
        // of the data task, a key due twice at one time gets a cycle per value. Allocates nothing.
        while (true) {
            long t = Long.MAX_VALUE;
            for (Feed<?> f : fedKeys) {
                t = Math.min(t, f.nextTimeNs());
            }
            if (t == Long.MAX_VALUE) {
                break;
            }
            step.runUntil(t);
            for (Feed<?> f : fedKeys) {
                if (f.nextTimeNs() == t) {
                    f.pending = f.channel.commits().get(f.next++);
                }
            }
            step.releaseNow(dataTask);
            feeder.rethrow();
        }
        step.runUntil(Math.max(clock.nanos(), recording.endNs()));
        Report report = monitor.stop();
        return new Result(report, dataTask, List.copyOf(fed), values);
    }

    private static <T extends StateValue<T>> Feed<T> feed(Key<T> key, Recording.KeyChannel channel) {
        return new Feed<>(new ValueCodec<>(key), channel);
    }

    /** @return the task's recorded execution times (end - start of each cycle), world ns, in order */
    static long[] recordedExecNs(Recording recording, String task) {
        Recording.TaskTimeline timeline = recording.tasks().get(task);
        if (timeline == null) {
            return new long[0];
        }
        int n = 0;
        for (Recording.Cycle c : timeline.cycles()) {
            n += c.message().outcome().equals("skipped") ? 0 : 1;
        }
        long[] execNs = new long[n];
        int i = 0;
        for (Recording.Cycle c : timeline.cycles()) {
            TaskCycleMessage m = c.message();
            if (!m.outcome().equals("skipped")) {
                execNs[i++] = Math.max(0, m.endNs() - m.startNs());
            }
        }
        return execNs;
    }

    /** One sensor key: its codec, recorded channel, output, and the value due now. */
    private static final class Feed<T extends StateValue<T>> {
        final ValueCodec<T> codec;
        final Recording.KeyChannel channel;
        Output<T> out;
        Recording.Commit pending;
        /** Index of the next commit to feed. */
        int next;

        Feed(ValueCodec<T> codec, Recording.KeyChannel channel) {
            this.codec = codec;
            this.channel = channel;
        }

        /** @return world time of the next commit to feed, or {@link Long#MAX_VALUE} when all are fed */
        long nextTimeNs() {
            return next < channel.commits().size() ? channel.commits().get(next).timeNs() : Long.MAX_VALUE;
        }

        void init(TaskSetup setup) {
            out = setup.produce(codec.key());
        }

        void publishPending() throws IOException {
            if (pending != null) {
                codec.decode(pending, out.value());
                out.publish();
                pending = null;
            }
        }
    }

    /** The data task of the replay: commits the sensor values handed to it. */
    private static final class Feeder implements Task {
        private final Feed<?>[] feeds;
        private IOException failure;

        Feeder(Feed<?>[] feeds) {
            this.feeds = feeds;
        }

        @Override
        public void initialize(TaskSetup setup) {
            for (Feed<?> f : feeds) {
                f.init(setup);
            }
        }

        @Override
        public void execute(long nowNs) {
            for (Feed<?> f : feeds) {
                try {
                    f.publishPending();
                } catch (IOException e) {
                    failure = e;
                    f.pending = null;
                }
            }
        }

        /** Ends the replay with a malformed value's message, on the replay's thread. */
        void rethrow() throws IOException {
            if (failure != null) {
                throw failure;
            }
        }
    }

    /** A controller task charged a recorded execution time per cycle: the real behavior runs, then the clock moves on. */
    private static final class Charged implements Task {
        private final Task task;
        private final ManualClock clock;
        private final long[] execNs;
        private int next;

        Charged(Task task, ManualClock clock, long[] execNs) {
            this.task = task;
            this.clock = clock;
            this.execNs = execNs;
        }

        @Override
        public void initialize(TaskSetup setup) throws Exception {
            task.initialize(setup);
        }

        @Override
        public void execute(long nowNs) throws Exception {
            try {
                task.execute(nowNs);
            } finally {
                if (execNs.length > 0) {
                    clock.advance(execNs[next]);
                    next = next + 1 == execNs.length ? 0 : next + 1;
                }
            }
        }

        @Override
        public boolean blocks() {
            return task.blocks();
        }

        @Override
        public void terminate() throws Exception {
            task.terminate();
        }
    }
}
