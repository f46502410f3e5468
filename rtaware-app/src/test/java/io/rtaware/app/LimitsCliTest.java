package io.rtaware.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.bench.BenchCommand;
import io.rtaware.app.cli.MemoryBudget;
import io.rtaware.app.run.RunCommand;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** Configurations that cannot work end with one line and exit status 2, before anything runs. */
class LimitsCliTest {

    private static final long HEAP_512_MB = 512L * 1024 * 1024;

    @TempDir
    Path dir;

    /** Commands as the launcher's default JVM (-Xmx512m) would see them, whatever heap the tests run in. */
    private static final CommandLine.IFactory HEAP_512 = new CommandLine.IFactory() {
        @Override
        @SuppressWarnings("unchecked")
        public <K> K create(Class<K> cls) throws Exception {
            if (cls == BenchCommand.class) {
                return (K) new BenchCommand(() -> new MemoryBudget(HEAP_512_MB, 0));
            }
            if (cls == RunCommand.class) {
                return (K) new RunCommand(() -> new MemoryBudget(HEAP_512_MB, 0));
            }
            return CommandLine.defaultFactory().create(cls);
        }
    };

    @Test
    void benchWithMoreTasksThanTheHeapHoldsIsRefusedWithTheNumbers() {
        CliRun r = CliRun.of(HEAP_512, "bench", "--tasks", "100000", "--duration", "1s");
        r.assertOneLineUserError("100000 task(s)");
        assertTrue(r.err().contains("KB of monitor bookkeeping per task") && r.err().contains("GB of heap"), r.err());
        assertTrue(r.err().contains("-Xmx"), "says how to raise it: " + r.err());
        assertFalse(r.out().contains("rtaware bench:"), "nothing ran");
    }

    @Test
    void tenThousandTasksFitTheDefaultHeapButTheirComparisonDoesNot() {
        // Issue 16: 10 000 tasks at 100 Hz on the pooled executor in the launcher's heap, with
        // 64 MB already in use (the JVM, the command's classes).
        long needed = MemoryBudget.times(10_000, io.rtaware.core.monitor.Monitor.estimatedHeapBytesPerTask());
        new MemoryBudget(HEAP_512_MB, 64L * 1024 * 1024).require(needed, "--tasks 10000");
        CliRun.of(HEAP_512, "bench", "--compare", "--executor", "pooled", "--tasks", "10000", "--duration", "1s")
                .assertOneLineUserError("10000 task(s) (44 KB of monitor and comparison bookkeeping per task)");
        CliRun.of(HEAP_512, "bench", "--sweep-tasks", "10,10000", "--duration", "1s")
                .assertOneLineUserError("10000 task(s) (44 KB of monitor and comparison bookkeeping per task)");
    }

    /**
     * Issue 38: {@code --workers 5000} ended in a 20-line OutOfMemoryError (unable to create native
     * thread). A worker runs one task at a time, and past 16 per core a pool is a thread per task.
     */
    @Test
    void moreWorkersThanTasksOrSixteenPerCoreAreRefusedUpFront() {
        int cores = Runtime.getRuntime().availableProcessors();
        CliRun.of("bench", "--executor", "pooled", "--workers", "5000", "--duration", "1s")
                .assertOneLineUserError("--workers must be 1 to 4 (at most one per task, 4 here, and 16 per core, "
                        + cores + " cores here), got 5000");
        int perCore = 16 * cores;
        CliRun.of(HEAP_512, "bench", "--executor", "pooled", "--tasks", Integer.toString(perCore + 1), "--workers",
                Integer.toString(perCore + 1), "--duration", "1s")
                .assertOneLineUserError("--workers must be 1 to " + perCore + " (at most one per task, " + (perCore + 1)
                        + " here, and 16 per core, " + cores + " cores here), got " + (perCore + 1));
    }

    /** The system's refusal of another thread, wherever a command meets it, is one line and status 1. */
    @Test
    void aThreadTheSystemRefusesIsOneLineAndStatusOne() {
        String refusal = "unable to create native thread: possibly out of memory or process/resource limits reached";
        CliRun r = CliRun.of(failingWith(new OutOfMemoryError(refusal)), "bench", "--duration", "1s");
        assertEquals(1, r.status(), r.toString());
        assertEquals("rtaware: the system refused another thread (" + refusal + "); run fewer tasks or --workers, or "
                + "raise the limit on threads (ulimit -u, pid_max, a container's pids limit)", r.err().strip());
        OutOfMemoryError heap = new OutOfMemoryError("Java heap space");
        assertSame(heap, assertThrows(OutOfMemoryError.class, () -> CliRun.of(failingWith(heap), "bench")),
                "any other OutOfMemoryError is not hidden");
    }

    /** A bench whose first look at the heap throws {@code error}, as a thread's start would. */
    private static CommandLine.IFactory failingWith(OutOfMemoryError error) {
        return new CommandLine.IFactory() {
            @Override
            @SuppressWarnings("unchecked")
            public <K> K create(Class<K> cls) throws Exception {
                if (cls == BenchCommand.class) {
                    return (K) new BenchCommand(() -> {
                        throw error;
                    });
                }
                return CommandLine.defaultFactory().create(cls);
            }
        };
    }

    @Test
    void aTraceCapacityThatCannotFitIsRefused() {
        String trace = dir.resolve("t.json").toString();
        CliRun.of(HEAP_512, "bench", "--trace", trace, "--trace-capacity", "2000000000", "--duration", "1s")
                .assertOneLineUserError("--trace-capacity 2000000000 (29 bytes per event)");
        CliRun.of(HEAP_512, "run", "--trace", trace, "--trace-capacity", "2000000000", "--out",
                dir.resolve("run").toString(), "--quiet").assertOneLineUserError("--trace-capacity 2000000000");
    }

    @Test
    void budgetArithmeticSaturates() {
        assertTrue(MemoryBudget.times(Long.MAX_VALUE / 2, 29) == Long.MAX_VALUE);
        assertTrue(MemoryBudget.add(Long.MAX_VALUE, 1) == Long.MAX_VALUE);
    }

    @Test
    void timeScaleIsBoundedInEveryCommand() {
        for (String command : new String[] {"run", "bench", "sim", "experiment"}) {
            CliRun.of(command, "--time-scale", "1e-300").assertOneLineUserError("time scale '1e-300' is out of range");
            CliRun.of(command, "--time-scale", "1e300").assertOneLineUserError("time scale '1e300' is out of range");
        }
    }

    @Test
    void liveBindThatDoesNotResolveIsOneLine() {
        CliRun.of("bench", "--live", "--live-bind", "no.such.invalid", "--duration", "1s")
                .assertOneLineUserError("--live-bind: cannot resolve 'no.such.invalid'");
        CliRun.of("run", "--live", "--live-bind", "no.such.invalid", "--out", dir.resolve("r").toString(), "--quiet")
                .assertOneLineUserError("--live-bind: cannot resolve 'no.such.invalid'");
    }

    @Test
    void liveBindToAForeignAddressIsOneLine() {
        CliRun.of("bench", "--live", "--live-bind", "8.8.8.8", "--duration", "200ms", "--quiet")
                .assertOneLineUserError("cannot serve the live view on 8.8.8.8:0");
        CliRun.of("run", "--live", "--live-bind", "8.8.8.8", "--out", dir.resolve("r").toString(), "--quiet")
                .assertOneLineUserError("cannot serve the live view on 8.8.8.8:0");
    }

    @Test
    void livePortInUseIsOneLine() throws IOException {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            String port = Integer.toString(taken.getLocalPort());
            CliRun.of("bench", "--live", "--live-port", port, "--duration", "200ms", "--quiet")
                    .assertOneLineUserError("cannot serve the live view on 127.0.0.1:" + port);
            CliRun.of("run", "--live", "--live-port", port, "--out", dir.resolve("r").toString(), "--quiet")
                    .assertOneLineUserError("cannot serve the live view on 127.0.0.1:" + port);
        }
    }
}
