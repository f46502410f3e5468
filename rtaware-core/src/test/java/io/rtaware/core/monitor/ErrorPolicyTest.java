package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.report.Report;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** CONTINUE, DISABLE_TASK and STOP_ALL on the step executor. */
class ErrorPolicyTest {

    private static final Key<Counter> COUNT = Counter.key("count");

    private final ManualClock clock = new ManualClock();
    private final RecordingListener events = new RecordingListener();
    private final List<Long> generationsSeen = new ArrayList<>();

    /** Publishes now (in ms) every cycle, and throws at {@code failAtMs} after publishing. */
    private static FnTask failingProducer(long failAtMs) {
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        return new FnTask(s -> out[0] = s.produce(COUNT), now -> {
            out[0].value().value = now / 1_000_000;
            out[0].publish();
            if (now == ms(failAtMs)) {
                throw new IllegalStateException("sensor glitch at " + failAtMs + " ms");
            }
        });
    }

    private FnTask recordingConsumer() {
        @SuppressWarnings("unchecked")
        Input<Counter>[] in = new Input[1];
        return new FnTask(s -> in[0] = s.consume(COUNT), now -> generationsSeen.add(in[0].value().value));
    }

    private Monitor monitor(ErrorPolicy policy, FnTask producer, FnTask consumer) {
        return Monitor.builder(clock).listener(events)
                .task(new TaskSpec("producer", Schedule.periodic(ms(10)), policy, producer))
                .task("consumer", Schedule.periodic(ms(10)), consumer).build();
    }

    @Test
    void continuePolicyKeepsRunningCountsTheErrorAndDoesNotCommitTheFailedCycle() {
        Monitor monitor = monitor(ErrorPolicy.CONTINUE, failingProducer(10), recordingConsumer());
        monitor.startStepped().runUntil(ms(40));

        TaskCounters c = monitor.counters("producer");
        assertEquals(4, c.runs(), "the task is still released after the error");
        assertEquals(1, c.errors(), "one error counted");
        assertEquals(List.of(0L, 0L, 20L, 30L), generationsSeen,
                "the value published by the failed cycle at 10 ms is never committed");
        assertEquals(3, monitor.feed("count").commits(), "three commits out of four cycles");
        assertEquals(List.of("error producer CONTINUE at=" + ms(10)),
                events.events.stream().filter(e -> e.startsWith("error")).toList(), "error event with policy");
        assertEquals("sensor glitch at 10 ms", events.errors.get(0).getMessage(), "the thrown exception is passed on");
        assertEquals(1, monitor.stop().task("producer").errors(), "errors in the report");
    }

    @Test
    void continueIsTheDefaultPolicy() {
        Monitor monitor = Monitor.builder(clock).task("t", Schedule.periodic(ms(10)), FnTask.of(now -> {
            throw new RuntimeException("always");
        })).build();
        monitor.startStepped().runUntil(ms(30));
        assertEquals(3, monitor.counters("t").runs(), "a failing task under the default policy keeps running");
        assertEquals(3, monitor.counters("t").errors(), "every failure counted");
    }

    @Test
    void disablePolicyStopsReleasingOnlyTheFailedTask() {
        Monitor monitor = monitor(ErrorPolicy.DISABLE_TASK, failingProducer(10), recordingConsumer());
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(50));

        assertEquals(2, monitor.counters("producer").runs(), "no release after the failing cycle at 10 ms");
        assertEquals(2, monitor.counters("producer").releases(), "a disabled task is not released any more");
        assertEquals(5, monitor.counters("consumer").runs(), "the other task goes on");
        assertEquals(4, monitor.counters("consumer").staleRuns(),
                "its input goes stale: new only at 0 ms (the 10 ms cycle failed), stale at 10..40 ms");
        assertEquals(1, events.count("state producer DISABLED at=" + ms(10)), "DISABLED state reported: " + events.events);
        assertFalse(monitor.isTerminated(), "DISABLE_TASK does not stop the monitor");
    }

    @Test
    void stopAllPolicyTerminatesTheMonitorBuildsTheReportAndCallsTheHandler() {
        FnTask producer = failingProducer(20);
        FnTask consumer = recordingConsumer();
        List<Report> handled = new ArrayList<>();
        Monitor monitor = monitor(ErrorPolicy.STOP_ALL, producer, consumer);
        monitor.onTermination(handled::add);
        StepExecutor step = monitor.startStepped();

        step.runUntil(ms(100));

        assertTrue(monitor.isTerminated(), "STOP_ALL terminates the monitor");
        assertFalse(step.step(), "nothing is released after STOP_ALL");
        assertEquals(3, monitor.counters("producer").runs(), "the producer ran at 0, 10 and 20 ms");
        assertEquals(2, monitor.counters("consumer").runs(), "the consumer ran at 0 and 10 ms, then everything stopped");
        assertEquals(1, handled.size(), "the termination handler is called once");
        Report report = monitor.report();
        assertNotNull(report, "the report is built");
        assertSame(report, handled.get(0), "the handler receives the monitor's report");
        assertEquals(1, report.task("producer").errors(), "the error is in the report");
        assertEquals(0.02, report.durationS(), 0.0, "the run lasted until the failure at 20 ms");
        assertEquals(1, producer.terminations, "terminate() called on the failed task");
        assertEquals(1, consumer.terminations, "terminate() called on the other task");
        assertSame(report, monitor.stop(), "a later stop() returns the same report");
        assertEquals(1, handled.size(), "and does not call the handler again");
    }
}
