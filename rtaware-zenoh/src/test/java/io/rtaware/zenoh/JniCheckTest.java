package io.rtaware.zenoh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The JNI layer under the JVM's own checks (issue 38): {@link #main} runs in a JVM of its own with
 * {@code -Xcheck:jni}, passing and receiving string arrays longer than the 16 local references a
 * native method may hold without asking (listen endpoints in, liveliness keys out), and must
 * print no JNI warning.
 */
class JniCheckTest {

    /** More elements than the local references a native method has without asking for more. */
    static final int ELEMENTS = 100;

    @Test
    @Requires(NativeZenohLayer.class)
    void longStringArraysCrossTheJniLayerWithoutAWarningUnderXcheckJni() throws Exception {
        Process jvm = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xcheck:jni",
                "-cp", System.getProperty("java.class.path"), JniCheckTest.class.getName()).redirectErrorStream(true).start();
        String output = new String(jvm.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(jvm.waitFor(60, TimeUnit.SECONDS), "the checked JVM ended");
        assertEquals(0, jvm.exitValue(), output);
        assertEquals(List.of(), output.lines().filter(l -> l.contains("WARNING") || l.contains("FATAL")).toList(),
                "-Xcheck:jni says nothing: " + output);
        assertTrue(output.contains("keys " + ELEMENTS), output);
    }

    /**
     * {@value #ELEMENTS} liveliness tokens listed (a String[] out of the native layer), then a
     * session listening on {@value #ELEMENTS} endpoints (a String[] into it). In that order: the
     * JVM raises a thread's allowance after each warning, which would hide the second.
     *
     * @param args none
     * @throws Exception if the native layer fails
     */
    public static void main(String[] args) throws Exception {
        ZenohLibrary.require();
        try (ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer())) {
            for (int i = 0; i < ELEMENTS; i++) {
                s.declareToken("@jni_check/" + i);
            }
            System.out.println("keys " + s.livelinessKeys("@jni_check/**", 2000).size());
        }
        List<String> listen = new ArrayList<>(Collections.nCopies(ELEMENTS, ZenohConfig.LOOPBACK_ANY_PORT));
        ZenohSession.open(ZenohConfig.loopbackPeer().withListen(listen)).close();
    }
}
