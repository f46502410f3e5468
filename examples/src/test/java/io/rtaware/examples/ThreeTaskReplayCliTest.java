package io.rtaware.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.RtawareCli;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code rtaware replay} on the example's recording, as a user would run it: the command line in a
 * JVM of its own whose class path lacks the example, which it gets only through {@code --classpath}.
 */
class ThreeTaskReplayCliTest {

    @TempDir
    static Path dir;
    private static Path recording;
    private static Path exampleClasses;

    @BeforeAll
    static void recordAShortRun() throws Exception {
        recording = dir.resolve("three-tasks.mcap");
        PrintStream discard = new PrintStream(PrintStream.nullOutputStream(), true, StandardCharsets.UTF_8);
        ThreeTaskController.Outcome outcome = ThreeTaskController.run(recording, Duration.ofMillis(500), discard, discard);
        assertEquals(0, outcome.recording().dropped(), "a recording without drops");
        exampleClasses = Path.of(ThreeTaskController.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    /** The output of one {@code rtaware} command line run in a JVM without the example's classes. */
    private record Cli(int status, String out, String err) {
    }

    private static Cli rtaware(String... args) throws IOException, InterruptedException, URISyntaxException {
        Path testClasses = Path.of(ThreeTaskReplayCliTest.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        String classPath = Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator))
                .filter(entry -> !Path.of(entry).toAbsolutePath().equals(exampleClasses.toAbsolutePath())
                        && !Path.of(entry).toAbsolutePath().equals(testClasses.toAbsolutePath()))
                .collect(Collectors.joining(File.pathSeparator));
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classPath, RtawareCli.class.getName()));
        command.addAll(List.of(args));
        Process process = new ProcessBuilder(command).redirectOutput(dir.resolve("out.txt").toFile())
                .redirectError(dir.resolve("err.txt").toFile()).start();
        int status = process.waitFor();
        return new Cli(status, Files.readString(dir.resolve("out.txt")), Files.readString(dir.resolve("err.txt")));
    }

    @Test
    void theCommandLineReplaysTheExampleIdenticallyFromItsClasspath() throws Exception {
        Cli replay = rtaware("replay", recording.toString(), "--classpath", exampleClasses.toString());
        assertEquals(0, replay.status(), replay.err());
        for (String task : List.of("pose", "slow", "drive")) {
            Matcher m = Pattern.compile("(?m)^" + task + "\\s+(\\d+)\\s+(\\d+)\\s").matcher(replay.out());
            assertTrue(m.find(), task + " replayed: " + replay.out());
            assertTrue(Long.parseLong(m.group(1)) > 0, task + " has cycles: " + replay.out());
            assertEquals(m.group(1), m.group(2), task + ": every cycle identical: " + replay.out());
        }
    }

    @Test
    void withOtherPeriodsTheExampleIsReplayedAsARun() throws Exception {
        Cli whatIf = rtaware("replay", recording.toString(), "--classpath", exampleClasses.toString(), "--periods", "slow=40ms");
        assertEquals(0, whatIf.status(), whatIf.err());
        assertTrue(whatIf.out().contains("what-if replay of " + recording), whatIf.out());
        assertTrue(whatIf.out().lines().anyMatch(l -> l.contains("slow=40") && l.contains("(recorded: ") && l.contains("slow=20")),
                whatIf.out());
    }

    @Test
    void withoutItsClassesTheProviderIsNamedInOneLine() throws Exception {
        Cli missing = rtaware("replay", recording.toString());
        assertEquals(2, missing.status(), missing.err());
        assertEquals(1, missing.err().lines().count(), missing.err());
        assertTrue(missing.err().contains("'" + ThreeTaskController.ID + "'") && missing.err().contains("--classpath"),
                missing.err());

        Path absent = dir.resolve("no-such-classes");
        Cli bad = rtaware("replay", recording.toString(), "--classpath", exampleClasses + File.pathSeparator + absent);
        assertEquals(2, bad.status(), bad.err());
        assertEquals(1, bad.err().lines().count(), bad.err());
        assertTrue(bad.err().contains("--classpath") && bad.err().contains(absent.toString()), bad.err());
        assertFalse(bad.err().contains("Exception"), bad.err());
    }
}
