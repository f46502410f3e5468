package ${package};

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.testing.TaskHarness;
import org.junit.jupiter.api.Test;

/**
 * The controller's tasks on stepped time: {@link TaskHarness} runs them through the real monitor on
 * a manual clock, so every age and every release is exact, with no sleeping.
 */
class SpeedGuardTest {

    private static long ms(long millis) {
        return millis * 1_000_000L;
    }

    private static Quantity metres(double value) {
        Quantity q = new Quantity();
        q.value = value;
        return q;
    }

    @Test
    void theGuardDrivesOnlyOnAFreshRangeWithClearance() {
        TaskHarness h = TaskHarness.builder().input(Quantity.NEAREST_M).task("guard", new SpeedGuard()).build();

        h.cycle("guard", ms(10));
        assertEquals(0.0, h.read(Quantity.SPEED_MPS).value, "no range yet: stop");

        h.publish(Quantity.NEAREST_M, metres(1.0), ms(20));
        h.cycle("guard", ms(50));
        assertEquals(SpeedGuard.DRIVE_MPS, h.read(Quantity.SPEED_MPS).value, "clear at 1.0 m: drive");

        h.publish(Quantity.NEAREST_M, metres(0.39), ms(60));
        h.cycle("guard", ms(100));
        assertEquals(0.0, h.read(Quantity.SPEED_MPS).value, "an obstacle at 0.39 m: stop");

        h.publish(Quantity.NEAREST_M, metres(1.0), ms(110));
        h.cycle("guard", ms(310));
        assertEquals(SpeedGuard.DRIVE_MPS, h.read(Quantity.SPEED_MPS).value, "a range exactly 200 ms old: drive");
        h.cycle("guard", ms(311));
        assertEquals(0.0, h.read(Quantity.SPEED_MPS).value, "the sensor went quiet 201 ms ago: stop");
    }

    @Test
    void theControllersTasksRunAtTheirPeriods() {
        RangeSensor sensor = new RangeSensor(nowNs -> nowNs < ms(500) ? 1.0 : 0.2);
        TaskHarness h = TaskHarness.builder()
                .task("sensor", Schedule.periodic(Controller.SENSOR_PERIOD), sensor)
                .task("guard", Schedule.periodic(Controller.GUARD_PERIOD), new SpeedGuard())
                .build();

        h.runUntil(ms(500));
        assertEquals(SpeedGuard.DRIVE_MPS, h.read(Quantity.SPEED_MPS).value, "clear for the first 500 ms: drive");
        h.runUntil(ms(600));
        assertEquals(0.0, h.read(Quantity.SPEED_MPS).value, "an obstacle at 0.2 m from 500 ms: stop");

        TaskCounters sensorCounters = h.counters("sensor");
        TaskCounters guardCounters = h.counters("guard");
        assertEquals(30, sensorCounters.releases(), "released at 0, 20, ..., 580 ms");
        assertEquals(12, guardCounters.releases(), "released at 0, 50, ..., 550 ms");
        assertEquals(0, sensorCounters.misses() + guardCounters.misses(), "nothing misses on stepped time");
    }
}
