package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.Counter;
import io.rtaware.core.FnTask;
import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The hooks of a recorder of every cycle: each cycle's outcome with the generation of each input
 * it read, and each committed value, in order, on the step executor.
 */
class CycleRecordTest {

    private static final Key<Counter> COUNT = Counter.key("count");

    private final ManualClock clock = new ManualClock();

    private static final class Recorder implements MonitorListener {
        final List<String> cycles = new ArrayList<>();
        final List<String> commits = new ArrayList<>();

        @Override
        public void onCycleRecord(TaskInfo task, CycleOutcome outcome, long releaseNs, long startNs, long endNs,
                                  long[] inputGenerations) {
            cycles.add(task.name() + " " + outcome + " r=" + releaseNs / 1_000_000 + " s=" + startNs / 1_000_000
                    + " e=" + endNs / 1_000_000 + " in=" + Arrays.toString(inputGenerations));
        }

        @Override
        public void onCommitValue(TaskInfo producer, int keyIndex, long generation, long nowNs, StateValue<?> value) {
            commits.add(producer.name() + " key" + keyIndex + " g" + generation + " v" + ((Counter) value).value);
        }
    }

    @Test
    void everyCycleIsRecordedWithItsOutcomeAndTheGenerationsItRead() {
        Recorder recorder = new Recorder();
        @SuppressWarnings("unchecked")
        Output<Counter>[] out = new Output[1];
        FnTask producer = new FnTask(s -> out[0] = s.produce(COUNT), now -> {
            out[0].value().value += 10;
            out[0].publish();
        });
        @SuppressWarnings("unchecked")
        Input<Counter>[] in = new Input[1];
        int[] cycle = {0};
        FnTask consumer = new FnTask(s -> in[0] = s.consume(COUNT), now -> {
            cycle[0]++;
            if (cycle[0] == 3) {
                clock.advance(ms(15)); // past the 10 ms deadline
            }
            if (cycle[0] == 4) {
                throw new IllegalStateException("fourth cycle fails");
            }
        });
        Monitor monitor = Monitor.builder(clock).listener(recorder)
                .task("producer", Schedule.periodic(ms(20)), producer)
                .task(new TaskSpec("consumer", Schedule.periodic(ms(10)), ErrorPolicy.CONTINUE, consumer)).build();
        assertEquals(List.of("count"), monitor.tasks().get(1).inputKeys());
        assertEquals(List.of(COUNT), monitor.keys());

        monitor.startStepped().runUntil(ms(50));

        assertEquals(List.of("producer key0 g1 v10", "producer key0 g2 v20", "producer key0 g3 v30"),
                recorder.commits);
        assertEquals(List.of(
                "consumer OK r=0 s=0 e=0 in=[1]",
                "consumer STALE r=10 s=10 e=10 in=[1]",
                "consumer MISS r=20 s=20 e=35 in=[2]",
                "consumer ERROR r=40 s=40 e=40 in=[3]"),
                recorder.cycles.stream().filter(c -> c.startsWith("consumer")).toList());
        assertEquals("producer OK r=0 s=0 e=0 in=[]", recorder.cycles.get(0));
    }
}
