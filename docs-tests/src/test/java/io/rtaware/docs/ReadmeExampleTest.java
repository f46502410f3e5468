package io.rtaware.docs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.testing.TaskHarness;
import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.DoubleSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The README's "Writing a task" example, taken from README.md itself (the section's one
 * {@code java} block), saved as the file its public class names and compiled against the
 * library: run in a JVM of its own with {@code java -cp} and stopped with SIGINT, as a user runs
 * it and presses Ctrl-C; and its tasks stepped through {@link TaskHarness}, so what the README
 * says of {@code Guard} holds. Nothing of the example is copied here.
 */
class ReadmeExampleTest {

    private static final Path README = Path.of("../README.md");
    private static final String SECTION = "Writing a task";
    private static final int SIGINT = 2;
    private static final int SIGTERM = 15;

    @TempDir
    static Path dir;
    /** The example's package, e.g. {@code com.example.guard}. */
    private static String pkg;
    /** Its public class, the one with {@code main}. */
    private static String mainClass;
    private static URLClassLoader example;

    @BeforeAll
    static void compileTheReadmesExample() throws IOException {
        List<JavaBlock> blocks = JavaBlock.of(README).stream().filter(b -> b.heading().equals(SECTION)).toList();
        assertEquals(1, blocks.size(), "README.md's '" + SECTION + "' has one java block");
        String code = blocks.get(0).code();
        assertTrue(blocks.get(0).isWholeFile(), "the block is a whole file, from its package declaration on");
        pkg = group(code, "^package ([\\w.]+);");
        mainClass = group(code, "^public (?:final )?class (\\w+)");
        List<UserCompiler.Problem> problems = UserCompiler.compile(
                Map.of(pkg.replace('.', '/') + "/" + mainClass + ".java", code), dir);
        assertEquals(List.of(), problems, "README.md's example compiles without a warning");
        example = new URLClassLoader(new URL[] {dir.resolve("classes").toUri().toURL()},
                ReadmeExampleTest.class.getClassLoader());
    }

    private static String group(String code, String regex) {
        Matcher m = Pattern.compile(regex, Pattern.MULTILINE).matcher(code);
        assertTrue(m.find(), "the example has " + regex);
        return m.group(1);
    }

    /**
     * The README's promise: pasted into a file, it runs until Ctrl-C and then prints the summary.
     * The two seconds are the scenario (how long the user lets it run), not a measure: the test
     * waits for the line that says the tasks run, and checks what the summary holds, not how
     * fast anything was.
     */
    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD) // a hang guard
    void pastedAsItIsItRunsUntilCtrlCAndThenPrintsTheSummary() throws Exception {
        String os = System.getProperty("os.name");
        assumeTrue(os.startsWith("Linux"), "Ctrl-C is sent as SIGINT with kill(1), here on Linux only, not on " + os);
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Path stderr = dir.resolve("stderr.txt");
        Process child = new ProcessBuilder(java.toString(), "-cp",
                dir.resolve("classes") + File.pathSeparator + UserCompiler.libraryClassPath(), pkg + "." + mainClass)
                .redirectError(stderr.toFile()).start();
        try (BufferedReader out = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8))) {
            String first = out.readLine();
            assertNotNull(first, "the example ended before saying it runs; stderr: " + Files.readString(stderr));
            assertEquals("rtaware: running 2 tasks; Ctrl-C stops them and prints the summary", first, "its first line");
            int signal = SIGINT;
            if (ignores(child.pid(), SIGINT)) {
                // Inherited from a test started in the background without job control; a terminal's
                // Ctrl-C reaches a program run in the foreground. The JVM ends on SIGTERM the same way.
                System.err.println("ReadmeExampleTest: SIGINT is ignored in this test's process, so in the example's "
                        + "too; it gets SIGTERM instead, which the JVM handles as it does SIGINT");
                signal = SIGTERM;
            }
            Thread.sleep(2_000); // the user lets it run for two seconds
            String kill = "kill -" + signal + " " + child.pid();
            assertEquals(0, new ProcessBuilder(kill.split(" ")).inheritIO().start().waitFor(), kill);
            List<String> rest = out.lines().toList();
            assertEquals(128 + signal, child.waitFor(), "the exit status of a JVM ended by signal " + signal
                    + "; stderr: " + Files.readString(stderr) + "; stdout: " + rest);

            assertTrue(!rest.isEmpty() && rest.get(0).startsWith("rtaware summary: "), "the summary follows: " + rest);
            for (String task : List.of("sensor", "guard")) {
                String[] row = row(rest, task);
                assertTrue(Long.parseLong(row[3]) > 0 && Long.parseLong(row[4]) > 0,
                        "'" + task + "' was released and ran: " + String.join(" ", row));
            }
            assertEquals(List.of("nearest_m", "sensor", "guard"), List.of(row(rest, "nearest_m")).subList(0, 3),
                    "the sensor's key and its reader");
            assertEquals(List.of("speed_mps", "guard"), List.of(row(rest, "speed_mps")).subList(0, 2), "the guard's key");
            assertTrue(!Files.readString(stderr).contains("Exception"), "no exception: " + Files.readString(stderr));
        } finally {
            child.destroyForcibly();
        }
    }

    /** @return the summary's row of a task or key, split at blanks */
    private static String[] row(List<String> summary, String name) {
        return summary.stream().filter(l -> l.startsWith(name + " ")).findFirst().map(l -> l.trim().split("\\s+"))
                .orElseThrow(() -> new AssertionError("no row '" + name + "' in " + summary));
    }

    /** @return true if the process ignores the signal (its {@code SigIgn} mask in /proc) */
    private static boolean ignores(long pid, int signal) throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc", Long.toString(pid), "status"))) {
            if (line.startsWith("SigIgn:")) {
                return (Long.parseUnsignedLong(line.substring("SigIgn:".length()).trim(), 16) & (1L << (signal - 1))) != 0;
            }
        }
        return false;
    }

    @Test
    @SuppressWarnings("rawtypes")
    void theGuardDrivesOnlyOnAFreshReadingOfAtLeastFortyCentimetres() throws Exception {
        Key nearest = key("NEAREST_M");
        Key speed = key("SPEED_MPS");
        TaskHarness h = TaskHarness.builder().input(nearest).task("guard", guard()).build();

        h.cycle("guard", ms(10));
        assertEquals(0.0, value(h, speed), "no reading yet: stop");

        publish(h, nearest, 1.0, ms(20));
        h.cycle("guard", ms(50));
        assertEquals(0.3, value(h, speed), "1.0 m clear, 30 ms old: drive");

        publish(h, nearest, 0.39, ms(60));
        h.cycle("guard", ms(100));
        assertEquals(0.0, value(h, speed), "an obstacle at 0.39 m: stop");

        publish(h, nearest, 1.0, ms(110));
        h.cycle("guard", ms(310));
        assertEquals(0.3, value(h, speed), "a reading exactly 200 ms old is still trusted");
        h.cycle("guard", ms(311));
        assertEquals(0.0, value(h, speed), "a reading 201 ms old has expired: stop");
    }

    @Test
    @SuppressWarnings("rawtypes")
    void theExampleControllerRunsEveryReleaseOnSteppedTime() throws Exception {
        AtomicReference<Double> rangeM = new AtomicReference<>(1.0);
        TaskHarness h = TaskHarness.builder()
                .task("sensor", Schedule.periodic(Duration.ofMillis(20)), sensor(rangeM::get))
                .task("guard", Schedule.periodic(Duration.ofMillis(50)), guard())
                .build();
        Key speed = key("SPEED_MPS");

        h.runUntil(ms(1000));
        assertEquals(0.3, value(h, speed), "a clear 1.0 m reading: drive");
        rangeM.set(0.2);
        h.runUntil(ms(1100));
        assertEquals(0.0, value(h, speed), "an obstacle at 0.2 m: stop");

        TaskCounters sensor = h.counters("sensor");
        TaskCounters guard = h.counters("guard");
        assertEquals(55, sensor.releases(), "the sensor is released every 20 ms before 1.1 s");
        assertEquals(22, guard.releases(), "the guard is released every 50 ms before 1.1 s");
        assertEquals(0, sensor.misses() + guard.misses(), "nothing misses on stepped time");
    }

    private static long ms(long millis) {
        return TimeUnit.MILLISECONDS.toNanos(millis);
    }

    // The example's classes are package-private in a package of the user's: reached by reflection.

    private static Task guard() throws ReflectiveOperationException {
        Constructor<?> c = example.loadClass(pkg + ".Guard").getDeclaredConstructor();
        c.setAccessible(true);
        return (Task) c.newInstance();
    }

    private static Task sensor(DoubleSupplier rangeM) throws ReflectiveOperationException {
        Constructor<?> c = example.loadClass(pkg + ".Sensor").getDeclaredConstructor(DoubleSupplier.class);
        c.setAccessible(true);
        return (Task) c.newInstance(rangeM);
    }

    /** @return the key that {@code Quantity} declares in the named static field */
    @SuppressWarnings("rawtypes")
    private static Key key(String field) throws ReflectiveOperationException {
        Field f = example.loadClass(pkg + ".Quantity").getDeclaredField(field);
        f.setAccessible(true);
        return (Key) f.get(null);
    }

    private static Field valueField() throws ReflectiveOperationException {
        Field f = example.loadClass(pkg + ".Quantity").getDeclaredField("value");
        f.setAccessible(true);
        return f;
    }

    @SuppressWarnings({"rawtypes", "unchecked"})
    private static void publish(TaskHarness h, Key key, double value, long atNs) throws ReflectiveOperationException {
        StateValue quantity = key.newBuffer();
        valueField().setDouble(quantity, value);
        h.publish(key, quantity, atNs);
    }

    @SuppressWarnings({"rawtypes", "unchecked"})
    private static double value(TaskHarness h, Key key) throws ReflectiveOperationException {
        return valueField().getDouble(h.read(key));
    }
}
