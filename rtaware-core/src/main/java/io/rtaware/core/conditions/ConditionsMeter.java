package io.rtaware.core.conditions;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import io.rtaware.core.report.ReportDocument;
import java.util.Map;
import java.util.Objects;

/**
 * Takes a run's conditions: the setup and the counters at {@link #start}, the counters and the
 * JVM's pauses at {@link Span#finish}, and the verdict by {@link MachineVerdict}'s rule. Costs
 * a few file reads at each end and a listener on the collectors in between; nothing on the
 * task threads.
 */
public final class ConditionsMeter {

    private final HostReader host;
    private final JvmProbe jvm;
    private final BuildInfo build;

    /**
     * @param host the machine's files
     * @param jvm the JVM
     * @param build rtaware's build
     */
    public ConditionsMeter(HostReader host, JvmProbe jvm, BuildInfo build) {
        this.host = Objects.requireNonNull(host, "host");
        this.jvm = Objects.requireNonNull(jvm, "jvm");
        this.build = Objects.requireNonNull(build, "build");
    }

    /** @return a meter of this process on this machine */
    public static ConditionsMeter ofThisProcess() {
        return new ConditionsMeter(new HostReader(HostFiles.system(), System::nanoTime), new PlatformJvmProbe(),
                BuildInfo.ofThisCode());
    }

    /** @return the machine's reader, for checks between runs */
    public HostReader host() {
        return host;
    }

    /**
     * Reads the setup and starts measuring.
     *
     * @param timeScale the run's time scale
     * @param realtime the run's real-time settings, or {@code none}
     * @return the span under way
     */
    public Span start(double timeScale, String realtime) {
        StaticConditions setup = StaticConditions.read(host, jvm, build, timeScale, realtime);
        JvmProbe.PauseWatch pauses = jvm.watchPauses();
        return new Span(setup, host.sample(), pauses);
    }

    /** A run under measurement. */
    public final class Span {
        private final StaticConditions setup;
        private final HostSample start;
        private final JvmProbe.PauseWatch pauses;
        private ThreadTimerSlack timerSlack;
        /** The machine's counters at the end of the window, null while it goes on. */
        private HostSample end;
        private Conditions finished;

        private Span(StaticConditions setup, HostSample start, JvmProbe.PauseWatch pauses) {
            this.setup = setup;
            this.start = start;
            this.pauses = pauses;
        }

        /**
         * Reports, with the conditions, the timer slack of the run's cycle threads (a monitor's
         * {@code timerSlack()}), read when the conditions are made.
         *
         * @param slack the observation
         * @return this span
         */
        public synchronized Span timerSlackOf(ThreadTimerSlack slack) {
            this.timerSlack = slack;
            return this;
        }

        /**
         * Ends the window now (once; later calls do nothing): what the machine and the JVM do
         * after this, such as building the report of thousands of tasks and collecting its
         * garbage, is not the run's. Register it with {@link
         * io.rtaware.core.monitor.Monitor#onTasksStopped}; without it, {@link #finish} ends the
         * window when it is called.
         */
        public synchronized void end() {
            if (end == null) {
                end = host.sample();
                pauses.close(); // the JVM may deliver the last pauses while closing
            }
        }

        /**
         * Ends the measurement, if {@link #end()} has not, and gives its conditions (once; later
         * calls return the same conditions).
         *
         * @param shortestPeriodWorldMs the run's shortest task period, ms of world time, or NaN
         *     when it has none; the JVM's pauses are judged against it in wall time (divided by the
         *     time scale): at time scale 10 a 10 ms period lasts 1 ms on the machine
         * @return the conditions with the verdict
         */
        public synchronized Conditions finish(double shortestPeriodWorldMs) {
            if (finished == null) {
                end();
                finished = between(end, shortestPeriodWorldMs);
            }
            return finished;
        }

        /**
         * The conditions from the start to now, by the same rule, for a view of the run while it
         * goes; the measurement goes on. Once {@link #finish} has run, its conditions. Reads the
         * machine's files: call it from an observer's thread, not a task's.
         *
         * @param shortestPeriodWorldMs as for {@link #finish}
         * @return the conditions so far, with the verdict on them
         */
        public synchronized Conditions sofar(double shortestPeriodWorldMs) {
            return finished != null ? finished : between(end != null ? end : host.sample(), shortestPeriodWorldMs);
        }

        private Conditions between(HostSample end, double shortestPeriodWorldMs) {
            double wallPeriodMs = shortestPeriodWorldMs / setup.timeScale();
            MeasuredConditions between = MeasuredConditions.between(start, end, pauses,
                    MachineVerdict.PAUSE_PERIOD_FRACTION * wallPeriodMs);
            MeasuredConditions measured = timerSlack == null ? between : between.withTimerSlack(timerSlack);
            return Conditions.of(setup, measured, MachineVerdict.of(measured, wallPeriodMs));
        }
    }

    /**
     * @param conditions a run's conditions
     * @return them as the string map of an MCAP metadata record ({@link Conditions#MCAP_METADATA}):
     *     the verdict, its reasons, and the setup and measured figures as JSON text
     */
    public static Map<String, String> metadata(Conditions conditions) {
        ObjectMapper mapper = ReportDocument.mapper().disable(SerializationFeature.INDENT_OUTPUT);
        try {
            return Map.of("machine", conditions.machine(),
                    "machine_reasons", String.join("; ", conditions.machineReasons()),
                    "rule", conditions.rule(),
                    "setup", mapper.writeValueAsString(conditions.setup()),
                    "measured", mapper.writeValueAsString(conditions.measured()));
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("conditions cannot be written as JSON", e);
        }
    }
}
