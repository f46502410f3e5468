package io.rtaware.core.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class ReportSectionsMachineTest {

    private static final AdviceItem EXEC = new AdviceItem("planner", "exec_near_period", 10, 25,
            Map.of("exec_p99_ms", 9.5), "'planner' needs 9.5 ms (p99) of its 10 ms period: lengthen the period to 25 ms");
    private static final AdviceItem NYQUIST = new AdviceItem("waypoint", "nyquist", 200, 100,
            Map.of("input", "odom"), "'waypoint' is slower than its input");

    @Test
    void onABusyMachineTheTaskIsNotBlamedForLongExecutionTimes() {
        List<AdviceItem> advice = ReportSections.onMachine(List.of(EXEC, NYQUIST), "busy",
                List.of("other processes used 1.6 of 2 CPUs (more than 0.10)"));
        AdviceItem machine = advice.get(0);
        assertEquals(ReportSections.MACHINE_RULE, machine.rule());
        assertEquals(10, machine.suggestedPeriodMs(), "no period change is advised");
        assertEquals("exec_near_period", machine.evidence().get("rule_not_applied"));
        assertEquals(9.5, machine.evidence().get("exec_p99_ms"), "the evidence is kept");
        assertTrue(machine.message().contains("the machine was busy (other processes used 1.6 of 2 CPUs"),
                machine.message());
        assertSame(NYQUIST, advice.get(1), "a rule about data rates is not the machine's doing");
    }

    @Test
    void onAQuietOrUnknownMachineTheAdviceIsUnchanged() {
        List<AdviceItem> advice = List.of(EXEC, NYQUIST);
        assertSame(advice, ReportSections.onMachine(advice, "quiet", List.of()));
        assertSame(advice, ReportSections.onMachine(advice, null, List.of()));
    }

    @Test
    void aDisturbedRunAlsoKeepsTheBlameOffTheTask() {
        assertEquals(ReportSections.MACHINE_RULE,
                ReportSections.onMachine(List.of(EXEC), "disturbed", List.of("a GC pause of 5 ms")).get(0).rule());
    }
}
