package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.core.conditions.HostFiles;
import io.rtaware.core.conditions.HostReader;
import io.rtaware.core.conditions.MachineVerdict;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * On the real machine (wall clock, tagged {@code wall-clock}): an experiment started beside a
 * CPU burner waits, saying why, and makes its run once the burner stops. Only where the machine
 * is quiet without the burner (other engineers' builds may load it: then skipped, saying so);
 * the waiting rule itself is tested exactly in {@code QuietGateTest}.
 */
class QuietGateEndToEndTest {

    @TempDir
    Path dir;

    @Test
    void anExperimentBesideABurnerWaitsAndRunsWhenTheBurnerStops() throws Exception {
        assumeTrue(Files.isReadable(Path.of("/proc/stat")), "needs Linux's /proc/stat");
        MachineCheck check = MachineCheck.overWindow(new HostReader(HostFiles.system(), System::nanoTime),
                Duration.ofMillis(500));
        MachineVerdict before = check.check().verdict();
        assumeTrue(before.quiet(), "the machine is not quiet without the burner (" + before.text() + "): skipped");
        ByteArrayOutputStream shown = new ByteArrayOutputStream();
        ProgressBar bar = new ProgressBar(new PrintStream(shown, true, StandardCharsets.UTF_8), false, System::nanoTime, 1);
        QuietGate gate = new QuietGate(check, s -> Thread.sleep((long) (Math.min(s, 0.5) * 1000)), System::nanoTime, 60,
                false);
        ExperimentPlan plan = new ExperimentPlan(ExperimentSets.paper().subList(0, 1), 1,
                new RunConditions("paper-room", 10, 1, null));
        ExperimentRunner runner = new ExperimentRunner(plan, JvmRunCommand.ofCurrentProcess(FakeRun.class.getName()), dir,
                bar).quietGate(gate);
        Process burner = new ProcessBuilder("sh", "-c", "while :; do :; done").start();
        Thread stopper = new Thread(() -> {
            try {
                Thread.sleep(3000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            burner.destroyForcibly();
        });
        List<RunResult> rows;
        try {
            stopper.start();
            rows = runner.run();
        } finally {
            burner.destroyForcibly();
            burner.waitFor(10, TimeUnit.SECONDS);
            stopper.join();
        }
        String out = shown.toString(StandardCharsets.UTF_8);
        assertEquals(1, rows.size(), out);
        RunMachine m = rows.get(0).machine();
        assertEquals("quiet", m.beforeRun(), "the run started once the machine was quiet: " + out);
        assertTrue(m.waitedS() >= 2.0, "it waited for the burner (stopped after 3 s): " + m.waitedS() + " s; " + out);
        assertTrue(out.contains("[waiting] waiting for a quiet machine") && out.contains("other processes used"), out);
    }
}
