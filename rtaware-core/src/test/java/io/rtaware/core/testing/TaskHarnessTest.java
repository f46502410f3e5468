package io.rtaware.core.testing;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.ReadStatus;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import java.time.Duration;
import org.junit.jupiter.api.Test;

/** The harness drives tasks through the real handles: the real rules hold, not a double's. */
class TaskHarnessTest {

    private static final Key<Counter> IN = Counter.key("in");
    private static final Key<Counter> OUT = Counter.key("out");

    /** Doubles its input; throws when the input is negative, after publishing. */
    private static final class Doubler implements Task {
        Input<Counter> in;
        Output<Counter> out;
        ReadStatus lastStatus;

        @Override
        public void initialize(TaskSetup setup) {
            in = setup.consume(IN, Duration.ofMillis(100));
            out = setup.produce(OUT);
        }

        @Override
        public void execute(long nowNs) {
            run();
        }

        void run() {
            lastStatus = in.status();
            out.value().value = 2 * in.value().value;
            out.publish();
            if (in.value().value < 0) {
                throw new IllegalArgumentException("negative");
            }
        }
    }

    private static Counter counter(long v) {
        Counter c = new Counter();
        c.value = v;
        return c;
    }

    @Test
    void aTaskDrivenByHandSeesScriptedInputsThroughItsRealHandles() {
        Doubler doubler = new Doubler();
        TaskHarness h = TaskHarness.builder().input(IN).task("doubler", doubler).build();

        assertNull(h.cycle("doubler", 0));
        assertEquals(ReadStatus.NONE, doubler.lastStatus, "nothing published yet");

        h.publish(IN, counter(21), ms(50));
        assertNull(h.cycle("doubler", ms(100)));
        assertEquals(ReadStatus.NEW, doubler.lastStatus);
        assertEquals(ms(50), doubler.in.ageNs(), "age from the scripted commit time");
        assertEquals(42, h.read(OUT).value);

        h.cycle("doubler", ms(200));
        assertEquals(ReadStatus.OLD, doubler.lastStatus);
        assertEquals(2, h.counters("doubler").staleRuns(), "the real rule: the cycles before the first commit and"
                + " without new input are stale");
        assertEquals(2, h.counters("doubler").expiredReads(), "the real rule: the read before any commit and the"
                + " one 150 ms old, against a 100 ms max age");
        assertEquals(3, h.generation(OUT), "one commit per cycle that published");
        assertEquals(3, doubler.out.commits(), "commits, as the real handle counts them");
    }

    @Test
    void aCycleThatThrowsCommitsNothingAndReturnsTheError() {
        Doubler doubler = new Doubler();
        TaskHarness h = TaskHarness.builder().input(IN).task("doubler", doubler).build();
        h.publish(IN, counter(5), 0);
        h.cycle("doubler", 0);
        h.publish(IN, counter(-1), ms(10));

        Throwable error = h.cycle("doubler", ms(20));

        assertEquals("negative", error.getMessage());
        assertEquals(10, h.read(OUT).value, "the publish of the failing cycle was discarded");
        assertEquals(1, h.generation(OUT), "and not committed");
        assertEquals(1, doubler.out.commits());
        assertEquals(1, h.counters("doubler").errors());
        Report report = h.stop();
        assertEquals(1, report.task("doubler").errors());
    }

    @Test
    void tasksOnTheirSchedulesRunAsInARun() {
        Doubler doubler = new Doubler();
        TaskHarness h = TaskHarness.builder().input(IN)
                .task("doubler", Schedule.periodic(ms(10)), doubler).build();
        h.publish(IN, counter(1), 0);
        h.runUntil(ms(100));

        Report report = h.stop();
        assertEquals(10, report.task("doubler").releases());
        assertEquals(9, report.task("doubler").staleRuns(), "the input was new only at the first cycle");
        assertEquals(10, report.key("out").commits());
    }

    @Test
    void misuseIsNamed() {
        TaskHarness h = TaskHarness.builder().input(IN).task("doubler", new Doubler())
                .task("tick", Schedule.periodic(ms(10)), FnTask.of(now -> { })).build();
        h.cycle("doubler", ms(10));
        assertThrows(IllegalArgumentException.class, () -> h.cycle("doubler", ms(5)), "time goes forward");
        assertThrows(IllegalArgumentException.class, () -> h.publish(OUT, counter(1), ms(20)), "not scripted");
        assertThrows(IllegalStateException.class, () -> h.cycle("tick", ms(20)), "periodic: not by hand");
        assertSame(h.monitor().clock(), h.clock());
    }
}
