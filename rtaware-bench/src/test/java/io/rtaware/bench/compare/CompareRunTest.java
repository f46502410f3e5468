package io.rtaware.bench.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import java.io.PrintStream;
import java.io.OutputStream;
import java.util.List;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;

/** Which rows a comparison runs: by family, by label, and without the thread-per-task ones beyond their limit. */
class CompareRunTest {

    private static final BusyWork WORK = BusyWork.calibrate();

    private static CompareRun comparison(int tasks, List<String> rows) {
        List<BenchSpec> specs = IntStream.rangeClosed(1, tasks).mapToObj(i -> BenchSpec.of("t" + i, 10_000_000, 0))
                .toList();
        return new CompareRun(specs, WORK, 1_000_000_000L, 2_000_000_000L, new PrintStream(OutputStream.nullOutputStream()),
                rows, 2, null, null);
    }

    @Test
    void labelsPickRowsInTheTablesOrder() {
        assertEquals(List.of("stpe-pooled", "netty-wheel", "agrona-wheel"),
                CompareRun.rows("agrona-wheel, netty-wheel,stpe-pooled,netty-wheel"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CompareRun.rows("netty-wheel,quartz"));
        assertEquals("no comparison row 'quartz'; rows: rtaware, rtaware-pooled, stpe, stpe-pooled, park-loop, "
                + "netty-wheel, agrona-wheel", e.getMessage());
    }

    @Test
    void everyFamilyHasTheParkLoopAndThePooledOneTheWheels() {
        assertEquals(CompareRun.ROWS, CompareRun.Family.ALL.rows());
        assertEquals(List.of("rtaware", "stpe", "park-loop"), CompareRun.Family.THREADED.rows());
        assertEquals(List.of("rtaware-pooled", "stpe-pooled", "park-loop", "netty-wheel", "agrona-wheel"),
                CompareRun.Family.POOLED.rows());
    }

    @Test
    void beyondAThousandTasksPerCoreTheThreadPerTaskRowsAreLeftOutAndNamed() {
        int limit = CompareRun.THREAD_PER_TASK_LIMIT_PER_CORE * Runtime.getRuntime().availableProcessors();
        CompareRun fits = comparison(limit, CompareRun.ROWS);
        assertEquals(CompareRun.ROWS, fits.rows());
        assertEquals(List.of(), fits.leftOut());

        CompareRun beyond = comparison(limit + 1, CompareRun.ROWS);
        assertEquals(List.of("rtaware-pooled", "stpe-pooled", "netty-wheel", "agrona-wheel"), beyond.rows());
        assertEquals(List.of("rtaware", "stpe", "park-loop"), beyond.leftOut());
    }
}
