package io.rtaware.experiment;

import io.rtaware.core.conditions.HostReader;
import io.rtaware.core.conditions.HostSample;
import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.conditions.MeasuredConditions;
import java.time.Duration;

/**
 * Looks at the machine before a run: is it quiet by {@link MachineVerdict}'s rule now? The
 * experiment's own process, idle between runs, is not counted as another process.
 */
@FunctionalInterface
public interface MachineCheck {

    /**
     * @return the verdict on the machine over a short window now
     * @throws InterruptedException if interrupted while measuring
     */
    MachineVerdict check() throws InterruptedException;

    /**
     * @param host the machine's files
     * @param window how long to measure
     * @return a check that measures the machine's CPU counters over the window
     */
    static MachineCheck overWindow(HostReader host, Duration window) {
        return () -> {
            HostSample start = host.sample();
            Thread.sleep(window.toMillis());
            return MachineVerdict.of(MeasuredConditions.between(start, host.sample(), null, Double.NaN), Double.NaN);
        };
    }
}
