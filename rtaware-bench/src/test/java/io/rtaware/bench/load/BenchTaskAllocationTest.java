package io.rtaware.bench.load;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;

/**
 * The bench task set (a chain, so inputs are copied in and outputs committed) allocates nothing
 * per cycle in steady state, on the step executor: the comparison's "alloc B/release" of rtaware
 * is then the framework's own.
 */
class BenchTaskAllocationTest {

    @Test
    void aChainOfBenchTasksAllocatesNothingPerCycleAfterWarmUp() {
        ManualClock clock = new ManualClock();
        BusyWork work = BusyWork.calibrate();
        Monitor.Builder builder = Monitor.builder(clock);
        String previous = null;
        for (int i = 1; i <= 4; i++) {
            builder.task("t" + i, Schedule.periodic(1_000_000), new BenchTask("t" + i, 0, previous, work));
            previous = "t" + i;
        }
        Monitor monitor = builder.build();
        StepExecutor step = monitor.startStepped();
        for (int i = 0; i < 200_000; i++) {
            step.step();
        }
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        // Steady state is reached once the JIT has compiled the cycle (on a loaded machine the
        // compiler lags, and a deoptimization rematerializes objects once); it must then stay at
        // zero for a whole window. Counts cycles, not time.
        long allocated = -1;
        for (int window = 0; window < 30 && allocated != 0; window++) {
            long before = bean.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < 100_000; i++) {
                step.step();
            }
            allocated = bean.getCurrentThreadAllocatedBytes() - before;
        }
        monitor.stop();
        assertEquals(0, allocated, "bytes allocated in the last window of 100000 cycles");
    }
}
