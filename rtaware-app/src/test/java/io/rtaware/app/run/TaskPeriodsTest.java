package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.app.UserError;
import org.junit.jupiter.api.Test;

class TaskPeriodsTest {

    @Test
    void namedTasksOverrideDefaults() {
        TaskPeriods p = TaskPeriods.parse("obstacle=10ms,planner=0.2s", TaskPeriods.paperSet4());
        assertEquals(100_000_000L, p.periodNs("waypoint"), "waypoint keeps Set 4's 100 ms");
        assertEquals(10_000_000L, p.periodNs("obstacle"));
        assertEquals(100_000_000L, p.periodNs("occupancy"));
        assertEquals(200_000_000L, p.periodNs("planner"));
        assertEquals("waypoint=100ms,obstacle=10ms,occupancy=100ms,planner=200ms", p.toString());
    }

    @Test
    void unknownTaskIsNamedWithTheKnownOnes() {
        UserError e = assertThrows(UserError.class, () -> TaskPeriods.parse("mapper=10", TaskPeriods.paperSet4()));
        assertEquals("unknown task 'mapper' in --periods; tasks: waypoint, obstacle, occupancy, planner", e.getMessage());
    }

    @Test
    void zeroNegativeAndNonDurationPeriodsAreRejectedWithTheValue() {
        assertEquals("period of 'obstacle' in --periods must be positive, got '0'",
                assertThrows(UserError.class, () -> TaskPeriods.parse("obstacle=0", TaskPeriods.paperSet4())).getMessage());
        String bad = assertThrows(UserError.class, () -> TaskPeriods.parse("obstacle=fast", TaskPeriods.paperSet4())).getMessage();
        assertEquals("period of 'obstacle' in --periods: 'fast' is not a duration (examples: 10ms, 2.5ms, 500us, 1s)", bad);
        assertThrows(UserError.class, () -> TaskPeriods.parse("obstacle=-5ms", TaskPeriods.paperSet4()));
        assertEquals("period of 'obstacle' in --periods: '50' has no unit: a duration needs one of ns, us, ms, s, min, h"
                + " (e.g. 50ms or 50s)",
                assertThrows(UserError.class, () -> TaskPeriods.parse("obstacle=50", TaskPeriods.paperSet4())).getMessage());
        assertThrows(UserError.class, () -> TaskPeriods.parse("obstacle", TaskPeriods.paperSet4()));
    }
}
