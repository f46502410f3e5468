package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.Scan;
import io.rtaware.core.data.Key;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.ManualClock;
import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/** Initialization: every violation of the task set is reported, with exact messages, all at once. */
class ConfigurationTest {

    private static final Key<Scan> LASER = Scan.key("laser");
    private static final Key<Counter> ODOMETRY = Counter.key("odometry");
    private static final Key<Counter> AVOID = Counter.key("motion.avoid");
    private static final Key<Counter> MAP = Counter.key("map");
    private static final Key<Counter> POSE = Counter.key("pose");
    private static final Key<Scan> POSE_AS_SCAN = Scan.key("pose");

    private final ManualClock clock = new ManualClock();

    private static FnTask declaring(FnTask.Init init) {
        return new FnTask(init, now -> { });
    }

    private static Schedule.Periodic periodic(long periodNs, long offsetNs, long deadlineNs) {
        return new Schedule.Periodic(periodNs, offsetNs, deadlineNs);
    }

    private Monitor.Builder robot() {
        return Monitor.builder(clock)
                .task("laser", Schedule.periodic(ms(100)), declaring(s -> s.produce(LASER)))
                .task("odometry", Schedule.periodic(ms(100)), declaring(s -> s.produce(ODOMETRY)))
                .task("avoid", Schedule.periodic(ms(100)), declaring(s -> {
                    s.consume(LASER);
                    s.produce(AVOID);
                }));
    }

    @Test
    void missingProducerNamesTaskKeyAndEveryProducedKey() {
        ConfigurationException e = assertThrows(ConfigurationException.class, () -> robot()
                .task("planner", Schedule.periodic(ms(100)), declaring(s -> s.consume(MAP))).build());

        assertEquals(List.of("task 'planner' consumes 'map' but no task produces it; produced keys: laser, odometry, motion.avoid"),
                e.violations(), "the produced keys are listed in declaration order");
        assertEquals(e.violations().get(0), e.getMessage(), "a single violation is the whole message");
    }

    @Test
    void missingProducerWithNothingProducedSaysNone() {
        ConfigurationException e = assertThrows(ConfigurationException.class, () -> Monitor.builder(clock)
                .task("planner", Schedule.periodic(ms(100)), declaring(s -> s.consume(MAP))).build());
        assertEquals(List.of("task 'planner' consumes 'map' but no task produces it; produced keys: (none)"),
                e.violations(), "violations");
    }

    @Test
    void everyViolationIsListedAtOnce() {
        Monitor.Builder builder = Monitor.builder(clock)
                .task("dup", Schedule.periodic(ms(10)), declaring(s -> { }))
                .task("dup", Schedule.periodic(ms(10)), declaring(s -> { }))
                .task("zero", periodic(0, 0, 0), declaring(s -> { }))
                .task("negative", periodic(-ms(5), 0, -ms(5)), declaring(s -> { }))
                .task("late", periodic(ms(10), 0, ms(12)), declaring(s -> { }))
                .task("early", periodic(ms(10), -ms(1), ms(10)), declaring(s -> { }))
                .task("soon", new Schedule.Once(-ms(2)), declaring(s -> { }))
                .task("broken", Schedule.periodic(ms(10)), declaring(s -> {
                    throw new IOException("no device /dev/ttyUSB0");
                }))
                .task("twice", Schedule.periodic(ms(10)), declaring(s -> {
                    s.produce(Counter.key("x"));
                    s.produce(Counter.key("x"));
                }))
                .task("p1", Schedule.periodic(ms(10)), declaring(s -> s.produce(POSE)))
                .task("p2", Schedule.periodic(ms(10)), declaring(s -> s.produce(POSE)))
                .task("reader", Schedule.periodic(ms(10)), declaring(s -> s.consume(POSE_AS_SCAN)))
                .task("fresh", Schedule.periodic(ms(10)), declaring(s -> s.consume(POSE, Duration.ZERO)))
                .task("planner", Schedule.periodic(ms(10)), declaring(s -> s.consume(MAP)));

        ConfigurationException e = assertThrows(ConfigurationException.class, builder::build);

        List<String> expected = List.of(
                "task name 'dup' is used by more than one task; names must be unique",
                "task 'zero' has period 0ns; a period must be positive",
                "task 'negative' has period -5ms; a period must be positive",
                "task 'late' has deadline 12ms; it must be positive and at most the period 10ms",
                "task 'early' has offset -1ms; an offset cannot be negative",
                "task 'soon' has offset -2ms; an offset cannot be negative",
                "task 'broken' failed to initialize: IOException: no device /dev/ttyUSB0",
                "task 'twice' declares 'x' more than once",
                "task 'fresh' declares max age PT0S for 'pose'; it must be positive",
                "key 'pose' is produced by tasks 'p1' and 'p2'; a key has exactly one producer",
                "task 'reader' consumes 'pose' as Scan but task 'p1' produces it as Counter",
                "task 'planner' consumes 'map' but no task produces it; produced keys: x, pose");
        assertEquals(expected, e.violations(), "every violation, once each, in the order found");
        assertTrue(e.getMessage().startsWith(expected.size() + " configuration errors:\n  "),
                "the message counts the violations: " + e.getMessage());
        for (String violation : expected) {
            assertTrue(e.getMessage().contains(violation), "the message lists: " + violation);
        }
    }

    @Test
    void initializeExceptionWithoutMessageIsStillNamed() {
        ConfigurationException e = assertThrows(ConfigurationException.class, () -> Monitor.builder(clock)
                .task("npe", Schedule.periodic(ms(10)), declaring(s -> {
                    throw new IllegalStateException();
                })).build());
        assertEquals(List.of("task 'npe' failed to initialize: IllegalStateException"), e.violations(), "violations");
    }

    @Test
    void consumingAndProducingTheSameKeyIsDeclaringItTwice() {
        ConfigurationException e = assertThrows(ConfigurationException.class, () -> Monitor.builder(clock)
                .task("loop", Schedule.periodic(ms(10)), declaring(s -> {
                    s.produce(POSE);
                    s.consume(POSE);
                })).build());
        assertEquals(List.of("task 'loop' declares 'pose' more than once"), e.violations(), "violations");
    }

    @Test
    void validTaskSetBuildsAndInitializesEachTaskOnce() {
        Monitor monitor = robot().build();
        assertEquals(List.of("laser", "odometry", "avoid"), monitor.tasks().stream().map(TaskInfo::name).toList(),
                "tasks in registration order");
        assertEquals(List.of(0, 1, 2), monitor.tasks().stream().map(TaskInfo::index).toList(), "dense indices");
        assertEquals(3, monitor.keyNames().size(), "one state variable per produced key: " + monitor.keyNames());
    }

    @Test
    void declaringDataAfterInitializationIsRefused() {
        AtomicReference<TaskSetup> kept = new AtomicReference<>();
        Monitor.builder(clock).task("sneaky", Schedule.periodic(ms(10)), declaring(kept::set)).build();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> kept.get().produce(POSE));
        assertEquals("task 'sneaky' declared data after initialization", e.getMessage(), "message");
    }

    @Test
    void nothingRunsWhenVerificationFails() {
        AtomicBoolean ran = new AtomicBoolean();
        assertThrows(ConfigurationException.class, () -> Monitor.builder(clock)
                .task("ok", Schedule.periodic(ms(10)), new FnTask(s -> { }, now -> ran.set(true)))
                .task("bad", periodic(0, 0, 0), declaring(s -> { })).build());
        assertFalse(ran.get(), "no task executes when the task set is invalid");
    }
}
