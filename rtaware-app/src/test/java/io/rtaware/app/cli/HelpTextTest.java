package io.rtaware.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import io.rtaware.app.RtawareCli;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * Help reads as prose (issue 34): placeholders name what the user gives, paragraphs are left to
 * picocli to wrap, the built-in scenarios are listed where a scenario is taken, and a mistyped
 * command or scenario gets the nearest name.
 */
class HelpTextTest {

    private static List<CommandLine> commands() {
        CommandLine top = RtawareCli.commandLine(CommandLine.defaultFactory());
        List<CommandLine> all = new ArrayList<>(List.of(top));
        all.addAll(top.getSubcommands().values());
        return all;
    }

    @Test
    void everyPlaceholderNamesWhatTheUserGives() {
        for (CommandLine c : commands()) {
            for (OptionSpec o : c.getCommandSpec().options()) {
                if (o.arity().max > 0) {
                    assertFalse(o.paramLabel().startsWith("<"), c.getCommandSpec().qualifiedName() + " " + o.longestName()
                            + " shows the field's name " + o.paramLabel() + " (give it a paramLabel: DURATION, FILE, N...)");
                }
            }
        }
    }

    /** A line of a description that ends mid-sentence was broken by hand: picocli wraps it again, raggedly. */
    @Test
    void noParagraphIsBrokenByHand() {
        for (CommandLine c : commands()) {
            CommandSpec spec = c.getCommandSpec();
            List<String[]> texts = new ArrayList<>(List.of(spec.usageMessage().description(), spec.usageMessage().footer()));
            spec.options().forEach(o -> texts.add(o.description()));
            for (String[] lines : texts) {
                for (int i = 0; i + 1 < lines.length; i++) {
                    String line = lines[i];
                    boolean example = line.startsWith("  ");
                    assertTrue(line.isBlank() || example || line.matches("(?s).*[.:!?]$"), spec.qualifiedName()
                            + ": a line ends mid-sentence, join it with the next: '" + line + "'");
                }
            }
        }
    }

    @Test
    void addressesAreNeverSplitAcrossLines() {
        Pattern url = Pattern.compile("(https?://)?[\\w-]+(\\.[\\w-]+)*\\.(dev|org|com|io|net)(/[^\\s)]*)?");
        for (CommandLine c : commands()) {
            String help = c.getUsageMessage(CommandLine.Help.Ansi.OFF);
            List<String> wanted = new ArrayList<>();
            for (OptionSpec o : c.getCommandSpec().options()) {
                Matcher m = url.matcher(String.join(" ", o.description()));
                while (m.find()) {
                    wanted.add(m.group().replaceAll("[.,;]+$", ""));
                }
            }
            for (String address : wanted) {
                assertTrue(help.contains(address), c.getCommandSpec().qualifiedName() + " --help splits " + address
                        + ":\n" + help);
            }
        }
    }

    @Test
    void everyBuiltInScenarioIsListedWhereAScenarioIsTaken() {
        int taking = 0;
        for (CommandLine c : commands()) {
            OptionSpec scenario = c.getCommandSpec().findOption("--scenario");
            if (scenario != null) {
                taking++;
                String help = c.getUsageMessage(CommandLine.Help.Ansi.OFF).replaceAll("\\s+", " ");
                for (String name : ScenarioLoader.BUILT_IN) {
                    assertTrue(help.contains(name), c.getCommandSpec().qualifiedName() + " --help names " + name);
                }
                assertEquals("NAME|FILE", scenario.paramLabel());
            }
        }
        assertEquals(4, taking, "run, sim, world and experiment take --scenario");
    }

    @Test
    void aMistypedCommandSuggestsTheNearestAndPointsAtTheTopHelp() {
        CliRun r = CliRun.of("bnech").assertOneLineUserError("did you mean 'bench'?");
        assertTrue(r.err().contains("(see: rtaware --help)"), r.err());
        assertFalse(r.err().contains("rtaware rtaware"), "the top command's name once: " + r.err());
        CliRun.of("bench", "--duraton", "1s").assertOneLineUserError("did you mean '--duration'?");
        assertTrue(CliRun.of("bench", "--duraton", "1s").err().contains("(see: rtaware bench --help)"));
    }

    @Test
    void aMistypedScenarioSuggestsTheNearest() {
        CliRun.of("world", "--scenario", "ofice", "--png", "world.png")
                .assertOneLineUserError("unknown scenario 'ofice'; did you mean 'office'? (built-in scenarios: paper-room, "
                        + "corridor, office; or give a scenario YAML file)");
    }
}
