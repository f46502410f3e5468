package io.rtaware.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.analysis.Advice;
import io.rtaware.core.analysis.PeriodAdvice;
import io.rtaware.core.analysis.PeriodAdvisor;
import io.rtaware.core.analysis.Schedulability;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.record.RunRecorder;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.robot.msg.MotionRequest;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Advice checked by what-if replays, exact on a recording made here: a pose every 10 ms for one
 * second, and a follower recorded at 20 ms whose every cycle took 30 ms (so it ran at 0, 40, 80,
 * ... ms and skipped every other release).
 */
class AdviceCheckTest {

    private static final long MS = 1_000_000L;

    @TempDir
    Path dir;

    private static final AdviceCheck.Controller FOLLOWER = periods -> List.of(new TaskSpec("follower",
            Schedule.periodic(periods.getOrDefault("follower", 20 * MS)), ErrorPolicy.CONTINUE,
            new SyntheticReplayTest.Follower(false)));

    private Recording recording() throws Exception {
        Path file = dir.resolve("slow-follower.mcap");
        RunRecorder recorder = SyntheticReplayTest.poseRecorder(file, 101);
        MotionRequest request = new MotionRequest();
        for (int k = 0; k < 25; k++) {
            long release = k * 40 * MS;
            request.request(0.01 * k, 0.5);
            recorder.commit(1, k + 1, release + 30 * MS, request);
            recorder.cycle(1, RunRecorder.OK, release, release, release + 30 * MS, 0, new long[] {1 + 4L * k});
        }
        recorder.finish();
        return Recording.load(McapReader.open(file), file);
    }

    /**
     * Replayed at 20 ms, the follower misses half its releases (each 30 ms cycle overruns and skips
     * the next). The advice, made from that replay, sees 30 ms of work (p99) against the 5 ms the
     * sampling of the 100 Hz pose asks for: no period fits, and it suggests the work, 30 ms. At
     * 30 ms every cycle ends on its deadline: no miss, so the change is kept.
     */
    @Test
    void aChangeTheReplayShowsBetterIsKeptWithBeforeAndAfterSideBySide() throws Exception {
        Recording recording = recording();
        Report before = AdviceCheck.replay(recording, FOLLOWER, Map.of());
        TaskReport at20 = before.task("follower");
        assertEquals(50, at20.releases(), "0, 20, ..., 980 ms");
        assertEquals(25, at20.skipped());
        assertEquals(50, at20.misses(), "25 late runs and 25 skipped releases");

        Advice advice = PeriodAdvisor.advise(before, 1);
        PeriodAdvice follower = advice.task("follower");
        assertEquals(PeriodAdvice.INFEASIBLE, follower.verdict(), follower.message());
        assertEquals(30.0, follower.suggestedPeriodMs());

        AdviceCheck.Result check = AdviceCheck.verify(recording, FOLLOWER, Set.of("follower"), before,
                w -> PeriodAdvisor.advise(before, 1, null, w));
        assertEquals(1, check.steps().size());
        AdviceCheck.Step step = check.steps().get(0);
        assertTrue(step.kept(), step.reason());
        assertEquals(100.0, step.missPctBefore());
        assertEquals(0.0, step.missPctAfter());
        TaskReport at30 = check.after().task("follower");
        assertEquals(30.0, at30.periodMs());
        assertEquals(0, at30.misses());
        assertEquals(PeriodAdvice.INFEASIBLE, check.advice().task("follower").verdict(), "kept as advised");
        String text = AdviceCheck.text(check, "slow-follower.mcap");
        assertTrue(text.contains("follower         20ms -> 30ms     kept: misses 100.00% -> 0.00% of the advised"
                + " tasks' releases"), text);
        assertTrue(text.contains("20ms -> 30ms       50 -> 34          50 -> 0         100.00 -> 0.00"), text);
    }

    /**
     * A change that makes the replay worse is withdrawn with its figures; the period stays. The
     * follower at 40 ms fits its 30 ms cycles (no miss); advice to run it at 20 ms (as if made
     * from figures that did not show the work) overruns every cycle in the replay.
     */
    @Test
    void aChangeTheReplayShowsWorseIsWithdrawnWithTheFigures() throws Exception {
        Recording recording = recording();
        AdviceCheck.Controller at40 = periods -> FOLLOWER.tasks(Map.of("follower",
                periods.getOrDefault("follower", 40 * MS)));
        Report before = AdviceCheck.replay(recording, at40, Map.of());
        assertEquals(0, before.task("follower").misses());
        PeriodAdvice shorter = new PeriodAdvice("follower", 40, 20, PeriodAdvice.SHORTEN, 0.03, 20.0, "exec p99",
                "sampling of 'odometry' (25 Hz)", List.of(), List.of(), List.of(), "'follower' 40 ms -> 20 ms");
        AdviceCheck.Result check = AdviceCheck.verify(recording, at40, Set.of("follower"), before, w -> new Advice(1,
                List.of(w.getOrDefault("follower", shorter)), Schedulability.analyze(before, 1)));
        AdviceCheck.Step step = check.steps().get(0);
        assertFalse(step.kept());
        assertEquals("a what-if replay shows more misses: 0.00% -> 100.00% of the advised tasks' releases",
                step.reason());
        PeriodAdvice withdrawn = check.advice().task("follower");
        assertEquals(PeriodAdvice.WITHDRAWN, withdrawn.verdict());
        assertEquals(40.0, withdrawn.suggestedPeriodMs(), "the period stays");
        assertEquals("'follower' keeps 40 ms: the suggested 20 ms is withdrawn, a what-if replay shows more misses:"
                + " 0.00% -> 100.00% of the advised tasks' releases (it was: 'follower' 40 ms -> 20 ms)",
                withdrawn.message());
        assertEquals(check.before(), check.after(), "nothing kept: the after is the before");
    }

    @Test
    void aTaskTheControllerCannotGiveAPeriodIsWithdrawnWithoutAReplay() throws Exception {
        Recording recording = recording();
        Report before = AdviceCheck.replay(recording, FOLLOWER, Map.of());
        AdviceCheck.Result check = AdviceCheck.verify(recording, FOLLOWER, Set.of(), before,
                w -> PeriodAdvisor.advise(before, 1, null, w));
        assertEquals("a what-if replay cannot give 'follower' a period", check.steps().get(0).reason());
        assertEquals(PeriodAdvice.WITHDRAWN, check.advice().task("follower").verdict());
    }
}
