package io.rtaware.core.conditions;

import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * The {@code conditions} object of rtaware's reports: the verdict on the machine, the rule that
 * gave it, the setup, and what was measured over the run.
 *
 * @param machine the verdict: {@code quiet}, {@code busy}, {@code disturbed} or {@code unknown}
 * @param machineReasons the figures behind it, with the thresholds they crossed
 * @param rule the rule, in words ({@link MachineVerdict#RULE})
 * @param setup what does not change during a run
 * @param measured what was measured over it
 */
public record Conditions(String machine, List<String> machineReasons, String rule, StaticConditions setup,
                         MeasuredConditions measured) {

    /** The section's name in report.json. */
    public static final String SECTION = "conditions";
    /** The MCAP metadata record that carries them. */
    public static final String MCAP_METADATA = "rtaware.conditions";

    /**
     * Validates the fields.
     *
     * @param machine the verdict, not null
     * @param machineReasons the figures behind it (copied)
     * @param rule the rule, in words
     * @param setup what does not change during a run
     * @param measured what was measured over it
     */
    public Conditions {
        Objects.requireNonNull(machine, "machine");
        machineReasons = List.copyOf(machineReasons);
    }

    /**
     * @param setup the setup
     * @param measured the measured span
     * @param verdict the verdict on it
     * @return the conditions
     */
    public static Conditions of(StaticConditions setup, MeasuredConditions measured, MachineVerdict verdict) {
        return new Conditions(verdict.verdict(), verdict.reasons(), MachineVerdict.RULE, setup, measured);
    }

    /** @return the verdict as one line, {@code machine: busy (...)} */
    public String summaryLine() {
        String load = measured == null || !Double.isFinite(measured.loadStart()) ? ""
                : String.format(Locale.ROOT, "load %.1f at start", measured.loadStart());
        return new MachineVerdict(machine, machineReasons, load).text();
    }
}
