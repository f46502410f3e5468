package io.rtaware.experiment;

import io.rtaware.core.conditions.HostReader;
import io.rtaware.core.conditions.HostSample;
import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.conditions.MeasuredConditions;
import java.time.Duration;
import java.util.Objects;

/**
 * Looks at the machine before a run: is it quiet by {@link MachineVerdict}'s rule now? The
 * experiment's own process, idle between runs, is not counted as another process.
 */
@FunctionalInterface
public interface MachineCheck {

    /**
     * What one look at the machine found: the verdict and the figures its rule judged, kept so that
     * each row of results.csv carries the readings its run was admitted on.
     *
     * @param verdict the verdict by {@link MachineVerdict}'s rule
     * @param otherCpus CPU used by other processes over the window, CPUs: the figure
     *     {@link MeasuredConditions#between} gives from every other process's own counters (held to
     *     within the tick noise of the machine's busy time), the one the rule compares with
     *     {@link MachineVerdict#OTHER_CPUS_MAX}; NaN if unknown
     * @param stealPct steal over the window, percent, or NaN
     * @param load1 the 1-minute load average at the window's end, or NaN
     */
    record Reading(MachineVerdict verdict, double otherCpus, double stealPct, double load1) {

        /**
         * Checks the verdict is there.
         *
         * @param verdict the verdict
         * @param otherCpus other processes' CPU, CPUs, or NaN
         * @param stealPct steal, percent, or NaN
         * @param load1 the load average, or NaN
         */
        public Reading {
            Objects.requireNonNull(verdict, "verdict");
        }

        /**
         * @param m a measured window
         * @return the verdict on it by the rule and the figures the rule read
         */
        public static Reading of(MeasuredConditions m) {
            return new Reading(MachineVerdict.of(m, Double.NaN), m.otherCpus(), m.stealPct(), m.loadEnd());
        }
    }

    /**
     * @return the verdict on the machine over a short window now, with its figures
     * @throws InterruptedException if interrupted while measuring
     */
    Reading check() throws InterruptedException;

    /**
     * @param host the machine's files
     * @param window how long to measure
     * @return a check that measures the machine's CPU counters over the window
     */
    static MachineCheck overWindow(HostReader host, Duration window) {
        return () -> {
            HostSample start = host.sample();
            Thread.sleep(window.toMillis());
            return Reading.of(MeasuredConditions.between(start, host.sample(), null, Double.NaN));
        };
    }
}
