package io.rtaware.core.task;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import org.junit.jupiter.api.Test;

class ScheduleTest {

    @Test
    void periodicDeadlineDefaultsToThePeriodWithoutOffset() {
        Schedule.Periodic p = Schedule.periodic(Duration.ofMillis(10));
        assertEquals(new Schedule.Periodic(10_000_000L, 0, 10_000_000L), p, "periodic(10ms)");
        assertEquals("periodic(10ms)", p.toString(), "toString");
        assertEquals("periodic", p.kind(), "kind");
    }

    @Test
    void fullPeriodicScheduleKeepsOffsetAndDeadline() {
        Schedule.Periodic p = Schedule.periodic(Duration.ofMillis(10), Duration.ofMillis(3), Duration.ofMillis(4));
        assertEquals(new Schedule.Periodic(10_000_000L, 3_000_000L, 4_000_000L), p, "fields");
        assertEquals("periodic(10ms, offset 3ms, deadline 4ms)", p.toString(), "toString");
    }

    @Test
    void withPeriodScalesAConstrainedDeadline() {
        Schedule.Periodic p = Schedule.periodic(Duration.ofMillis(10), Duration.ZERO, Duration.ofMillis(4));
        assertEquals(new Schedule.Periodic(20_000_000L, 0, 8_000_000L), p.withPeriod(20_000_000L), "deadline scales");
        assertEquals(new Schedule.Periodic(20_000_000L, 0, 20_000_000L),
                Schedule.periodic(10_000_000L).withPeriod(20_000_000L), "deadline = period stays equal");
    }

    @Test
    void onceAndContinuousKinds() {
        assertEquals("once", Schedule.once().kind(), "once");
        assertEquals("once", Schedule.once().toString(), "once toString");
        assertEquals("once(offset 7ms)", new Schedule.Once(7_000_000L).toString(), "once with offset");
        assertEquals("continuous", Schedule.continuous().kind(), "continuous");
    }
}
