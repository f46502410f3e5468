package io.rtaware.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import io.rtaware.app.RtawareCli;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/**
 * Every option that takes a duration reads it through {@link DurationConverter}: a number without
 * a unit is one line naming the value and the units, exit status 2 ({@code bench --duration 10} ran
 * 10 ms and exited 0; {@code player-probe --listen 3} listened 3 ms and exited 1 with no message).
 */
class DurationOptionsTest {

    private static final String UNITS = "a duration needs one of ns, us, ms, s, min, h";

    /** @return subcommand name and option name of every option of every subcommand that holds a duration */
    private static List<String[]> durationOptions() {
        List<String[]> found = new ArrayList<>();
        CommandLine top = RtawareCli.commandLine(CommandLine.defaultFactory());
        top.getSubcommands().forEach((name, sub) -> {
            for (OptionSpec o : sub.getCommandSpec().options()) {
                boolean converted = o.converters().length == 1 && o.converters()[0] instanceof DurationConverter;
                String field = o.userObject() instanceof Field f ? f.getName() : "";
                boolean holdsTime = field.endsWith("Ns") || field.endsWith("S") || field.endsWith("Ms");
                assertEquals(holdsTime, converted, name + " " + o.longestName() + " (field " + field
                        + "): a time is read as a duration with its unit, and only a time");
                if (converted) {
                    assertEquals("DURATION", o.paramLabel(), name + " " + o.longestName() + " names what it takes");
                    found.add(new String[] {name, o.longestName()});
                }
            }
        });
        return found;
    }

    @Test
    void everyDurationOptionOfEverySubcommandRefusesANumberWithoutAUnit() {
        List<String[]> options = durationOptions();
        List<String> names = options.stream().map(o -> o[0] + " " + o[1]).toList();
        for (String expected : new String[] {"bench --duration", "bench --period", "bench --work", "bench --warmup",
                "bench --segment", "player-probe --listen", "sim --message-timeout", "run --stuck-after",
                "run --live-linger", "experiment --quiet-wait"}) {
            assertTrue(names.contains(expected), expected + " among " + names);
        }
        CommandLine top = RtawareCli.commandLine(CommandLine.defaultFactory());
        for (String[] o : options) {
            List<String> args = new ArrayList<>(List.of(o[0]));
            for (PositionalParamSpec p : top.getSubcommands().get(o[0]).getCommandSpec().positionalParameters()) {
                if (p.arity().min > 0) {
                    args.add("127.0.0.1:1");
                }
            }
            args.addAll(List.of(o[1], "10"));
            CliRun.of(args.toArray(String[]::new)).assertOneLineUserError("'10' has no unit: " + UNITS);
        }
    }

    @Test
    void benchDurationTenIsRefusedNotRunForTenMilliseconds() {
        CliRun r = CliRun.of("bench", "--duration", "10").assertOneLineUserError("--duration");
        assertTrue(r.err().contains("'10' has no unit: " + UNITS + " (e.g. 10ms or 10s)"), r.err());
        assertFalse(r.out().contains("misses"), "nothing ran: " + r.out());
    }

    @Test
    void zeroNeedsNoUnit() {
        CliRun.of("bench", "--duration", "0").assertOneLineUserError("--duration must be positive, got 0ns");
    }
}
