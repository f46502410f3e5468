package io.rtaware.rt;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** JNA is an optional dependency: without it the module still loads, and says so in one line. */
class WithoutJnaTest {

    @Test
    void withoutJnaRealtimeIsOneLineAndTheSleeperIsAbsent(@TempDir Path dir) throws Exception {
        String classPath = System.getProperty("surefire.test.class.path", System.getProperty("java.class.path"));
        String withoutJna = Arrays.stream(classPath.split(File.pathSeparator))
                .filter(entry -> !Path.of(entry).getFileName().toString().startsWith("jna-"))
                .collect(Collectors.joining(File.pathSeparator));
        assertFalse(withoutJna.equals(classPath), "JNA was on the test class path to be removed: " + classPath);
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Process process = new ProcessBuilder(java.toString(), "-cp", withoutJna, WithoutJnaMain.class.getName())
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        assertEquals(true, process.waitFor(60, TimeUnit.SECONDS), "the child JVM ended");
        List<String> errLines = Files.readAllLines(err, StandardCharsets.UTF_8);
        assertEquals(0, process.exitValue(), "exit status; stderr: " + errLines);
        assertEquals(List.of("rtaware: --realtime unavailable (JNA (net.java.dev.jna:jna) is not on the class path);"
                + " running with normal threads"), errLines, "one line names what is missing, no stack trace");
        assertEquals(List.of("threadSetup=null sleeper=false"), Files.readAllLines(out, StandardCharsets.UTF_8),
                "normal threads and parking instead");
    }
}
