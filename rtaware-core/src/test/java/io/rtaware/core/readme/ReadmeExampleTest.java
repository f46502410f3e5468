package io.rtaware.core.readme;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.SummaryTable;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.testing.TaskHarness;
import io.rtaware.core.time.SystemClock;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.DoubleSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The README's "Writing a task" example (README.md, the first {@code java} block), compiled and
 * run. The code between the {@code readme:begin} and {@code readme:end} markers of this file is
 * that block, line for line once its indentation is removed; {@link #readmeShowsThisCode()} fails
 * when the two drift apart, so change them together.
 */
class ReadmeExampleTest {

    private static final Path SOURCE = Path.of("src/test/java/io/rtaware/core/readme/ReadmeExampleTest.java");
    private static final Path README = Path.of("../README.md");

    @Test
    void theExampleBuildsStartsAndStopsOnTheSystemClock() {
        // readme:begin monitor
        Monitor monitor = Monitor.builder(new SystemClock())
            .task("sensor", Schedule.periodic(Duration.ofMillis(20)), new Sensor(() -> 1.0))
            .task("guard", Schedule.periodic(Duration.ofMillis(50)), new Guard())
            .build();                   // the data graph is checked here, buffers are allocated
        monitor.onTermination(report -> System.out.print(SummaryTable.format(report)));
        monitor.start();                // monitor.stop() ends the run and prints the summary
        // readme:end monitor
        Report report = monitor.stop();

        assertNotNull(report.task("sensor"), "the report has the sensor task");
        assertNotNull(report.task("guard"), "the report has the guard task");
        assertEquals("sensor", monitor.producer(Quantity.NEAREST_M.name()), "the sensor produces nearest_m");
        assertEquals(List.of("guard"), monitor.consumers(Quantity.NEAREST_M.name()), "the guard consumes nearest_m");
    }

    @Test
    void theGuardDrivesOnlyOnAFreshReadingOfAtLeastFortyCentimetres() {
        TaskHarness h = TaskHarness.builder().input(Quantity.NEAREST_M).task("guard", new Guard()).build();

        h.cycle("guard", ms(10));
        assertEquals(0.0, h.read(Quantity.SPEED_MPS).value, "no reading yet: stop");

        h.publish(Quantity.NEAREST_M, quantity(1.0), ms(20));
        h.cycle("guard", ms(50));
        assertEquals(0.3, h.read(Quantity.SPEED_MPS).value, "1.0 m clear, 30 ms old: drive");

        h.publish(Quantity.NEAREST_M, quantity(0.39), ms(60));
        h.cycle("guard", ms(100));
        assertEquals(0.0, h.read(Quantity.SPEED_MPS).value, "an obstacle at 0.39 m: stop");

        h.publish(Quantity.NEAREST_M, quantity(1.0), ms(110));
        h.cycle("guard", ms(310));
        assertEquals(0.3, h.read(Quantity.SPEED_MPS).value, "a reading exactly 200 ms old is still trusted");
        h.cycle("guard", ms(311));
        assertEquals(0.0, h.read(Quantity.SPEED_MPS).value, "a reading 201 ms old has expired: stop");
    }

    @Test
    void theExampleControllerRunsEveryReleaseOnSteppedTime() {
        AtomicReference<Double> rangeM = new AtomicReference<>(1.0);
        TaskHarness h = TaskHarness.builder()
                .task("sensor", Schedule.periodic(Duration.ofMillis(20)), new Sensor(rangeM::get))
                .task("guard", Schedule.periodic(Duration.ofMillis(50)), new Guard())
                .build();

        h.runUntil(ms(1000));
        assertEquals(0.3, h.read(Quantity.SPEED_MPS).value, "a clear 1.0 m reading: drive");
        rangeM.set(0.2);
        h.runUntil(ms(1100));
        assertEquals(0.0, h.read(Quantity.SPEED_MPS).value, "an obstacle at 0.2 m: stop");

        TaskCounters sensor = h.counters("sensor");
        TaskCounters guard = h.counters("guard");
        assertEquals(55, sensor.releases(), "the sensor is released every 20 ms before 1.1 s");
        assertEquals(22, guard.releases(), "the guard is released every 50 ms before 1.1 s");
        assertEquals(0, sensor.misses() + guard.misses(), "nothing misses on stepped time");
    }

    @Test
    void readmeShowsThisCode() throws IOException {
        String source = Files.readString(SOURCE, StandardCharsets.UTF_8);
        String expected = region(source, "classes") + "\n" + region(source, "monitor");
        String readme = Files.readString(README, StandardCharsets.UTF_8);
        Matcher block = Pattern.compile("```java\n(.*?)```", Pattern.DOTALL).matcher(readme);
        assertTrue(block.find(), "README.md has a java block");
        assertEquals(expected, block.group(1),
                "README.md's first java block is the code between this file's readme markers");
    }

    private static Quantity quantity(double value) {
        Quantity q = new Quantity();
        q.value = value;
        return q;
    }

    /** The lines between the markers of {@code name}, with their common indentation removed. */
    private static String region(String source, String name) {
        String begin = "// readme:begin " + name;
        String end = "// readme:end " + name;
        int from = source.indexOf(begin);
        int to = source.indexOf(end);
        assertTrue(from >= 0 && to > from, "markers of region '" + name + "' in " + SOURCE);
        List<String> lines = new ArrayList<>(List.of(source.substring(source.indexOf('\n', from) + 1, to).split("\n", -1)));
        lines.remove(lines.size() - 1);   // the marker line's own indentation
        int indent = lines.stream().filter(l -> !l.isBlank())
                .mapToInt(l -> l.length() - l.stripLeading().length()).min().orElse(0);
        StringBuilder text = new StringBuilder();
        for (String line : lines) {
            text.append(line.isBlank() ? "" : line.substring(indent)).append('\n');
        }
        return text.toString();
    }
}

// readme:begin classes
/** One number that tasks share; each task reads its own copy, never the writer's object. */
final class Quantity implements StateValue<Quantity> {
    static final Key<Quantity> NEAREST_M = Key.of("nearest_m", Quantity.class, Quantity::new);
    static final Key<Quantity> SPEED_MPS = Key.of("speed_mps", Quantity.class, Quantity::new);
    double value;

    @Override public void copyFrom(Quantity source) { value = source.value; }
}

/** Publishes the range to the nearest obstacle, read from a sensor, once per release. */
final class Sensor implements Task {
    private final DoubleSupplier rangeM;
    private Output<Quantity> nearest;

    Sensor(DoubleSupplier rangeM) { this.rangeM = rangeM; }

    @Override public void initialize(TaskSetup setup) { nearest = setup.produce(Quantity.NEAREST_M); }

    @Override public void execute(long nowNs) {
        nearest.value().value = rangeM.getAsDouble();
        nearest.publish();              // committed when the cycle returns
    }
}

/** Drives at 0.3 m/s unless an obstacle is nearer than 0.4 m or the reading is over 200 ms old. */
final class Guard implements Task {
    private Input<Quantity> nearest;
    private Output<Quantity> speed;

    @Override public void initialize(TaskSetup setup) {
        nearest = setup.consume(Quantity.NEAREST_M, Duration.ofMillis(200));
        speed = setup.produce(Quantity.SPEED_MPS);
    }

    @Override public void execute(long nowNs) {
        boolean clear = nearest.hasValue() && !nearest.isExpired() && nearest.value().value >= 0.4;
        speed.value().value = clear ? 0.3 : 0.0;
        speed.publish();
    }
}
// readme:end classes
