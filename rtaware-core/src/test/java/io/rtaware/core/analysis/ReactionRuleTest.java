package io.rtaware.core.analysis;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ReactionConstraint;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The reaction rule: {@code speed x (period + input age p99) + stopping <= range}, exact on
 * hand-built reports, and the declaration's way from {@code TaskSetup} into the report.
 */
class ReactionRuleTest {

    /** A Koala at 0.2 m/s behind a URG: 0.2 m to stop in, 26 mm stopping, scans 76.6 ms old at delivery. */
    private static final ReactionConstraint KOALA_0_2 = new ReactionConstraint("laser", 0.2, 0.026, 0.2, 76.6);

    private static Report avoiderAt(double periodMs, ReactionConstraint reaction) {
        TaskReport avoider = Reports.task("obstacle", periodMs, 100, 100, 100, 100, 0, 0).withReaction(reaction);
        return Reports.report(List.of(avoider), List.of(Reports.key("laser", "player", 10.0, "obstacle")));
    }

    private static PeriodAdvice advice(Report report) {
        return PeriodAdvisor.advise(report, 1).task("obstacle");
    }

    private static PeriodBound reactionItem(Report report) {
        return advice(report).bounds().stream().filter(b -> b.rule().equals(PeriodBound.REACTION)).findFirst()
                .orElseThrow();
    }

    @Test
    void namesTheLargestSafePeriodAndAcceptsAPeriodWithinIt() {
        // age p99 = 76.6 + 0.99 * 100 = 175.6 ms; bound = 1000 * (0.2 - 0.026) / 0.2 - 175.6 = 694.4 ms
        PeriodBound item = reactionItem(avoiderAt(50, KOALA_0_2));
        assertEquals(PeriodBound.UPPER, item.side());
        assertEquals(694.4, item.ms(), 1e-9);
        assertEquals(175.6, (double) item.evidence().get("input_age_p99_ms"), 1e-9);
        assertEquals(694.4, (double) item.evidence().get("max_safe_period_ms"), 1e-9);
        assertEquals(true, item.evidence().get("safe"));
        assertEquals(50.0, advice(avoiderAt(50, KOALA_0_2)).suggestedPeriodMs(), "a safe period stays");
        // needed = 0.2 * (50 + 175.6) / 1000 + 0.026 = 0.07112 m
        assertEquals(0.071, (double) item.evidence().get("needed_m"), 1e-12);
        assertEquals("reaction to 'laser' (0.2 m in range at 0.2 m/s, input age p99 175.6 ms)", item.label());
        assertEquals("assumes obstacles stand still: the gap closes at the robot's own speed",
                item.evidence().get("assumption"));
    }

    @Test
    void flagsAPeriodBeyondTheBound() {
        PeriodBound item = reactionItem(avoiderAt(800, KOALA_0_2));
        assertEquals(false, item.evidence().get("safe"));
        PeriodAdvice advice = advice(avoiderAt(800, KOALA_0_2));
        assertEquals(PeriodAdvice.SHORTEN, advice.verdict());
        assertEquals(50.0, advice.suggestedPeriodMs(), "the sampling of the 10 Hz laser binds before the reaction");
        assertEquals(List.of(50.0, 694.4), advice.bounds().stream().filter(b -> !b.lower()).map(PeriodBound::ms)
                .toList());
        // needed = 0.2 * 975.6 / 1000 + 0.026 = 0.22112 m > 0.2 m
        assertEquals(0.221, (double) item.evidence().get("needed_m"), 1e-12);
    }

    @Test
    void saysWhenNoPeriodIsFastEnough() {
        // 0.6 m/s: stopping 0.198 m of the 0.2 m; 1000 * 0.002 / 0.6 = 3.33 ms < 175.6 ms of age
        Report report = avoiderAt(10, new ReactionConstraint("laser", 0.6, 0.198, 0.2, 76.6));
        PeriodBound item = reactionItem(report);
        assertEquals(false, item.evidence().get("safe"));
        assertEquals(1000 * 0.002 / 0.6 - 175.6, (double) item.evidence().get("max_safe_period_ms"), 1e-3);
        assertEquals(PeriodAdvice.INFEASIBLE, advice(report).verdict());
    }

    @Test
    void anObstacleMovingTowardTheRobotClosesTheGapAtTheSumOfBothSpeeds() {
        // a person at 1.0 m/s: closing 1.2 m/s; bound = 1000 * (0.2 - 0.026) / 1.2 - 175.6 = -30.6 ms: none is fast enough
        ReactionConstraint person = new ReactionConstraint("laser", 0.2, 0.026, 0.2, 76.6, 1.0);
        PeriodBound item = reactionItem(avoiderAt(50, person));
        assertEquals(1.2, (double) item.evidence().get("closing_speed_mps"), 1e-12);
        assertEquals(1000 * 0.174 / 1.2 - 175.6, (double) item.evidence().get("max_safe_period_ms"), 1e-3);
        assertEquals(false, item.evidence().get("safe"));
        assertTrue(item.label().contains("at 1.2 m/s") && item.evidence().get("assumption").toString().startsWith(
                "assumes obstacles move toward the robot at up to 1 m/s: the gap closes at 1.2 m/s"), item.toString());
        // a slow cart at 0.05 m/s: closing 0.25 m/s; bound = 1000 * 0.174 / 0.25 - 175.6 = 520.4 ms, below the 694.4 ms of still obstacles
        PeriodBound cart = reactionItem(avoiderAt(50, new ReactionConstraint("laser", 0.2, 0.026, 0.2, 76.6, 0.05)));
        assertEquals(520.4, (double) cart.evidence().get("max_safe_period_ms"), 1e-9);
        assertEquals(0.05, (double) cart.evidence().get("obstacle_speed_mps"), 0.0);
    }

    @Test
    void aTaskWithoutADeclarationGetsNoReactionBound() {
        Report report = Reports.report(List.of(Reports.task("obstacle", 50, 100, 100, 100, 100, 0, 0)),
                List.of(Reports.key("laser", "player", 10.0, "obstacle")));
        assertTrue(advice(report).bounds().stream().noneMatch(b -> b.rule().equals(PeriodBound.REACTION)));
    }

    @Test
    void theDeclarationTravelsFromTaskSetupIntoTheReport() {
        Key<Counter> laser = Counter.key("laser");
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        FnTask producer = new FnTask(s -> out[0] = s.produce(laser), now -> out[0].publish());
        FnTask avoider = new FnTask(s -> {
            s.consume(laser);
            s.declareReaction(KOALA_0_2);
        }, now -> { });
        Monitor monitor = Monitor.builder(new ManualClock())
                .task("player", Schedule.periodic(ms(100)), producer)
                .task("obstacle", Schedule.periodic(ms(50)), avoider).build();
        monitor.startStepped().runUntil(ms(1000));
        Report report = monitor.stop();
        assertEquals(KOALA_0_2, report.task("obstacle").reaction());
        assertNull(report.task("player").reaction());
        PeriodBound item = reactionItem(report);
        assertEquals(10.0, (double) item.evidence().get("input_rate_hz"), 1e-9, "laser commits every 100 ms");
        assertEquals(694.4, (double) item.evidence().get("max_safe_period_ms"), 1e-9);
    }

    @Test
    void rejectsImpossibleDeclarations() {
        assertThrows(IllegalArgumentException.class, () -> new ReactionConstraint("laser", 0, 0.01, 0.2, 0));
        assertThrows(IllegalArgumentException.class, () -> new ReactionConstraint("laser", 0.1, -0.01, 0.2, 0));
        assertThrows(IllegalArgumentException.class, () -> new ReactionConstraint("laser", 0.1, 0.01, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new ReactionConstraint("laser", 0.1, 0.01, 0.2, -1));
    }
}
