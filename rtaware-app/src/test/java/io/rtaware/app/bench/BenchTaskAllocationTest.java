package io.rtaware.app.bench;

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
        long before = bean.getCurrentThreadAllocatedBytes();
        for (int i = 0; i < 100_000; i++) {
            step.step();
        }
        long allocated = bean.getCurrentThreadAllocatedBytes() - before;
        monitor.stop();
        assertEquals(0, allocated, "bytes allocated over 100000 steady-state cycles");
    }
}
