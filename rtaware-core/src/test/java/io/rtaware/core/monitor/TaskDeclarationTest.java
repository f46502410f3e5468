package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.Scan;
import io.rtaware.core.data.Key;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.ReactionConstraint;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** A task's declarations read without a monitor, as replay reads them, with the monitor's rules. */
class TaskDeclarationTest {

    private static final Key<Scan> LASER = Scan.key("laser");
    private static final Key<Counter> ODOMETRY = Counter.key("odometry");
    private static final Key<Counter> AVOID = Counter.key("motion.avoid");

    private static TaskSpec spec(String name, FnTask.Init init) {
        return new TaskSpec(name, Schedule.periodic(ms(50)), ErrorPolicy.CONTINUE, new FnTask(init, now -> { }));
    }

    @Test
    void inputsWithTheirMaxAgeOutputsAndReactionInDeclarationOrder() {
        ReactionConstraint reaction = new ReactionConstraint("laser", 0.5, 0.1, 2.0, 10.0);
        TaskDeclaration declared = TaskDeclaration.of(spec("avoid", s -> {
            s.consume(ODOMETRY);
            s.produce(AVOID);
            s.consume(LASER, Duration.ofMillis(200));
            s.declareReaction(reaction);
        }));

        assertEquals("avoid", declared.task());
        assertEquals(List.of(new TaskDeclaration.DeclaredInput(ODOMETRY, Long.MAX_VALUE),
                new TaskDeclaration.DeclaredInput(LASER, ms(200))), declared.inputs(), "inputs in declaration order");
        assertFalse(declared.inputs().get(0).hasMaxAge(), "no max age declared");
        assertTrue(declared.inputs().get(1).hasMaxAge(), "200 ms declared");
        assertEquals(Scan.class, declared.inputs().get(1).key().type(), "the key carries its type");
        assertEquals(List.of(AVOID), declared.outputs(), "outputs");
        assertEquals(reaction, declared.reaction(), "reaction");
    }

    @Test
    void aTaskThatDeclaresNothingHasNoInputsOutputsOrReaction() {
        TaskDeclaration declared = TaskDeclaration.of(spec("idle", s -> { }));
        assertEquals(List.of(), declared.inputs());
        assertEquals(List.of(), declared.outputs());
        assertNull(declared.reaction());
    }

    @Test
    void theInputOrderIsTheOrderTheMonitorRecordsGenerationsIn() {
        FnTask.Init init = s -> {
            s.consume(LASER);
            s.consume(ODOMETRY);
        };
        TaskDeclaration declared = TaskDeclaration.of(spec("reader", init));
        Monitor monitor = Monitor.builder(new ManualClock())
                .task("laser", Schedule.periodic(ms(50)), new FnTask(s -> s.produce(LASER), now -> { }))
                .task("odometry", Schedule.periodic(ms(50)), new FnTask(s -> s.produce(ODOMETRY), now -> { }))
                .task(spec("reader", init))
                .build();
        TaskInfo reader = monitor.tasks().stream().filter(t -> t.name().equals("reader")).findFirst().orElseThrow();
        assertEquals(reader.inputKeys(), declared.inputs().stream().map(in -> in.key().name()).toList());
    }

    @Test
    void initializationFailuresAndBrokenDeclarationsAreTheMonitorsViolations() {
        ConfigurationException failed = assertThrows(ConfigurationException.class, () -> TaskDeclaration.of(
                spec("broken", s -> {
                    throw new IOException("no device /dev/ttyUSB0");
                })));
        assertEquals(List.of("task 'broken' failed to initialize: IOException: no device /dev/ttyUSB0"),
                failed.violations());

        ConfigurationException twice = assertThrows(ConfigurationException.class, () -> TaskDeclaration.of(
                spec("twice", s -> {
                    s.produce(AVOID);
                    s.consume(LASER, Duration.ZERO);
                    s.consume(AVOID);
                })));
        assertEquals(List.of("task 'twice' declares max age PT0S for 'laser'; it must be positive",
                "task 'twice' declares 'motion.avoid' more than once"), twice.violations());
    }

    @Test
    void theTaskSeesAManualClockAtZeroAndIsInitializedOnce() {
        AtomicInteger initializations = new AtomicInteger();
        TaskDeclaration.of(spec("clocked", s -> {
            initializations.incrementAndGet();
            assertEquals(0, s.clock().nanos(), "world time 0");
            assertEquals("clocked", s.taskName());
            assertEquals(Schedule.periodic(ms(50)), s.schedule());
        }));
        assertEquals(1, initializations.get());
    }

    @Test
    void theDeclarationIsACopy() {
        TaskDeclaration declared = TaskDeclaration.of(spec("w", s -> s.produce(AVOID)));
        assertThrows(UnsupportedOperationException.class, () -> declared.outputs().add(LASER));
    }
}
