package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.PythonPeers;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/** Reads a recording's metadata with the independent Python {@code mcap} reader. */
final class McapMetadataCheck {

    private static final String SCRIPT = String.join("\n",
            "import sys, json",
            "from mcap.reader import make_reader",
            "with open(sys.argv[1], 'rb') as f:",
            "    for m in make_reader(f).iter_metadata():",
            "        if m.name == 'rtaware.conditions':",
            "            print(m.metadata['machine'])",
            "            json.loads(m.metadata['measured'])",
            "            json.loads(m.metadata['setup'])");

    private McapMetadataCheck() {
    }

    /**
     * @param file a recording
     * @param machine the verdict its {@code rtaware.conditions} record must carry
     */
    static void assertConditionsRecord(Path file, String machine) throws Exception {
        String python = PythonPeers.python();
        Process p = new ProcessBuilder(python, "-c", SCRIPT, file.toString()).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the Python reader finished");
        assertEquals(0, p.exitValue(), output);
        assertEquals(machine, output.strip(), "the rtaware.conditions metadata record, read by Python's mcap");
    }
}
