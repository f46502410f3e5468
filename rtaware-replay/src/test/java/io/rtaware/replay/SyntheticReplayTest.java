package io.rtaware.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import io.rtaware.record.RecordingListener;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RunRecorder;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Replay on small recordings made here with the project's recorder: exact replay catches a
 * behavior that is not a function of its inputs and names where; a recorder drop is reported as
 * not replayable; what-if periods show exactly the misses, skipped releases and stale runs the
 * rules give.
 */
class SyntheticReplayTest {

    private static final long MS = 1_000_000L;

    @TempDir
    Path dir;

    /** Publishes a new pose every cycle. */
    static final class Sensor implements Task {
        private Output<Odometry> out;
        private int n;

        @Override
        public void initialize(TaskSetup setup) {
            out = setup.produce(RobotKeys.ODOMETRY);
        }

        @Override
        public void execute(long nowNs) {
            out.value().xM = 0.1 * n++;
            out.value().serverTimeS = nowNs / 1e9;
            out.publish();
        }
    }

    /** Turns the pose into a request; from its fourth cycle on, adds noise from an unseeded random if noisy. */
    static final class Follower implements Task {
        private final boolean noisy;
        private final Random random = new Random();
        private Input<Odometry> pose;
        private Output<MotionRequest> request;
        private int cycles;

        Follower(boolean noisy) {
            this.noisy = noisy;
        }

        @Override
        public void initialize(TaskSetup setup) {
            pose = setup.consume(RobotKeys.ODOMETRY);
            request = setup.produce(RobotKeys.MOTION_AVOID);
        }

        @Override
        public void execute(long nowNs) {
            double noise = noisy && cycles >= 3 ? random.nextDouble() : 0;
            cycles++;
            request.value().request(pose.value().xM + noise, pose.isNew() ? 0.5 : -0.5);
            request.publish();
        }
    }

    static List<TaskSpec> graphOf(boolean noisy, long followerPeriodNs) {
        return List.of(new TaskSpec("sensor", Schedule.periodic(10 * MS), ErrorPolicy.CONTINUE, new Sensor()),
                new TaskSpec("follower", Schedule.periodic(followerPeriodNs), ErrorPolicy.CONTINUE, new Follower(noisy)));
    }

    private Recording record(boolean noisy) throws Exception {
        Path file = dir.resolve(noisy ? "noisy.mcap" : "steady.mcap");
        Monitor.Builder builder = Monitor.builder(new ManualClock());
        graphOf(noisy, 25 * MS).forEach(builder::task);
        Monitor monitor = builder.build();
        RunRecorder recorder = RecordingListener.attach(monitor, file, new RecordingPlan());
        StepExecutor step = monitor.startStepped();
        step.runUntil(300 * MS);
        monitor.stop();
        assertEquals(0, recorder.finish().dropped());
        return Recording.load(McapReader.open(file), file);
    }

    @Test
    void aBehaviorThatIsAFunctionOfItsInputsReplaysIdenticallyInEveryCycle() throws Exception {
        Recording recording = record(false);
        ExactReplay.TaskResult r = ExactReplay.replay(recording, () -> graphOf(false, 25 * MS), "follower");
        assertEquals(12, r.cycles(), "releases at 0, 25, ..., 275 ms");
        assertEquals(12, r.identical());
        assertEquals(0, r.different());
        assertNull(r.firstDifference());
        assertEquals(0, r.inputsMoved(), "one thread, one clock: every input committed at its recorded time");
        assertEquals(12, r.execNs().getTotalCount());
    }

    @Test
    void anUnseededRandomInTheOutputIsCaughtAtItsFirstCycleWithKeyAndField() throws Exception {
        Recording recording = record(true);
        ExactReplay.TaskResult r = ExactReplay.replay(recording, () -> graphOf(true, 25 * MS), "follower");
        assertEquals(12, r.cycles());
        assertEquals(3, r.identical(), "the first three cycles add no noise");
        assertEquals(9, r.different());
        ExactReplay.Difference d = r.firstDifference();
        assertNotNull(d);
        assertEquals(3, d.cycle());
        assertEquals(75 * MS, d.releaseNs());
        assertEquals("motion.avoid", d.key());
        assertEquals("vxMps", d.field());
    }

    @Test
    void aValueTheRecorderDroppedMakesTheRestNotReplayableInsteadOfADifference() throws Exception {
        Path file = dir.resolve("dropped.mcap");
        RunRecorder recorder = new RunRecorder(file, List.of("sensor", "follower"), List.of(List.of(), List.of("odometry")),
                List.of(RobotKeys.ODOMETRY, RobotKeys.MOTION_AVOID), new RecordingPlan());
        Odometry pose = new Odometry();
        MotionRequest request = new MotionRequest();
        for (int k = 1; k <= 4; k++) {
            long t = (k - 1) * 20 * MS;
            pose.xM = 0.1 * (k - 1);
            if (k != 3) {
                recorder.commit(0, k, t, pose); // generation 3 is "dropped"
            }
            request.request(pose.xM, 0.5);
            recorder.commit(1, k, t + MS, request);
            recorder.cycle(1, RunRecorder.OK, t, t, t + MS, 0, new long[] {k});
        }
        recorder.finish();
        Recording recording = Recording.load(McapReader.open(file), file);
        ExactReplay.TaskResult r = ExactReplay.replay(recording, () -> graphOf(false, 20 * MS), "follower");
        assertEquals(4, r.cycles());
        assertEquals(2, r.identical());
        assertEquals(0, r.different());
        assertEquals(2, r.notReplayable());
        assertEquals(2, r.firstNotReplayable().cycle());
        assertTrue(r.firstNotReplayable().reason().contains("generation 3 of input 'odometry'"),
                r.firstNotReplayable().reason());
    }

    /**
     * A pose every 10 ms from 0 to 100 ms; the follower recorded at 50 ms with 30 ms cycles
     * (releases 0, 50, 100, 150; the last ends at 180 ms).
     */
    private Recording whatIfRecording() throws Exception {
        Path file = dir.resolve("whatif.mcap");
        RunRecorder recorder = poseRecorder(file, 11);
        for (int k = 0; k < 4; k++) {
            long release = k * 50 * MS;
            recorder.cycle(1, RunRecorder.OK, release, release, release + 30 * MS, 0, new long[] {1 + 5L * k});
        }
        recorder.finish();
        return Recording.load(McapReader.open(file), file);
    }

    /**
     * @param file where to record
     * @param poses how many poses 'player' commits, one every 10 ms from 0
     * @return a recorder of 'player' and 'follower' (which reads odometry) with the poses committed
     */
    static RunRecorder poseRecorder(Path file, int poses) throws Exception {
        RunRecorder recorder = new RunRecorder(file, List.of("player", "follower"), List.of(List.of(), List.of("odometry")),
                List.of(RobotKeys.ODOMETRY, RobotKeys.MOTION_AVOID), new RecordingPlan());
        Odometry pose = new Odometry();
        for (int k = 1; k <= poses; k++) {
            pose.xM = 0.01 * k;
            recorder.commit(0, k, (k - 1) * 10 * MS, pose);
        }
        return recorder;
    }

    private static TaskReport follower(Recording recording, long periodNs) throws Exception {
        WhatIfReplay.Result result = WhatIfReplay.replay(recording, List.of(new TaskSpec("follower",
                Schedule.periodic(periodNs), ErrorPolicy.CONTINUE, new Follower(false))), List.of(new TaskSpec("follower",
                Schedule.periodic(periodNs), ErrorPolicy.CONTINUE, new Follower(false))));
        Report report = result.report();
        assertEquals("player", result.dataTask(), "the recording's data task feeds the sensor stream");
        assertEquals(List.of("odometry"), result.sensorKeys());
        assertEquals(11, result.sensorCommits());
        return report.task("follower");
    }

    @Test
    void whatIfAtTheRecordedPeriodMissesNothingAndRunsStaleOnceAfterTheSensorsStop() throws Exception {
        TaskReport t = follower(whatIfRecording(), 50 * MS);
        assertEquals(4, t.releases(), "0, 50, 100, 150 ms");
        assertEquals(4, t.runs());
        assertEquals(0, t.misses());
        assertEquals(0, t.skipped());
        assertEquals(1, t.staleRuns(), "150 ms: nothing new since 100 ms");
    }

    @Test
    void whatIfWithAPeriodShorterThanTheRecordedExecutionTimeMissesAndSkipsEveryOtherRelease() throws Exception {
        TaskReport t = follower(whatIfRecording(), 20 * MS);
        // Runs at 0, 40, 80, 120, 160 ms, each charged 30 ms: each ends past its 20 ms deadline and
        // skips the release it overran (20, 60, 100, 140, 180 ms).
        assertEquals(10, t.releases());
        assertEquals(5, t.runs());
        assertEquals(5, t.skipped());
        assertEquals(10, t.misses());
        assertEquals(1, t.staleRuns(), "160 ms: nothing new since the values committed at 110 ms");
    }

    /**
     * A bench's world time is the machine's monotonic clock (an hour after boot, say), and its
     * tasks read no sensor: the replay starts at the first recorded release, not at 0 (which made
     * an hour of releases), and runs no data task.
     */
    @Test
    void whatIfOfARecordingWhoseWorldTimeStartsLateStartsWhereTheRecordingDoes() throws Exception {
        long t0 = 3_600_000 * MS;
        Path file = dir.resolve("late.mcap");
        RunRecorder recorder = new RunRecorder(file, List.of("sensor"), List.of(List.of()), List.of(RobotKeys.ODOMETRY),
                new RecordingPlan());
        Odometry pose = new Odometry();
        for (int k = 0; k < 100; k++) {
            long release = t0 + k * 10 * MS;
            recorder.commit(0, k + 1, release + MS, pose);
            recorder.cycle(0, RunRecorder.OK, release, release, release + MS, 0, new long[0]);
        }
        recorder.finish();
        Recording recording = Recording.load(McapReader.open(file), file);
        List<TaskSpec> sensor = List.of(new TaskSpec("sensor", Schedule.periodic(10 * MS), ErrorPolicy.CONTINUE,
                new Sensor()));
        List<TaskSpec> probe = List.of(new TaskSpec("sensor", Schedule.periodic(10 * MS), ErrorPolicy.CONTINUE,
                new Sensor()));
        Report report = WhatIfReplay.replay(recording, sensor, probe).report();
        assertEquals(List.of("sensor"), report.tasks().stream().map(TaskReport::name).toList(), "no data task");
        assertEquals(100, report.task("sensor").releases(), "t0, t0 + 10 ms, ..., t0 + 990 ms");
        assertEquals(0, report.task("sensor").misses());
    }
}
