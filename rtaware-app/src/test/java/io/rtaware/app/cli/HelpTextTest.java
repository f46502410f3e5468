package io.rtaware.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import io.rtaware.app.RtawareCli;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.util.ArrayList;
import java.util.List;
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

    /**
     * A word with punctuation inside ({@code ui.perfetto.dev}, {@code a:10ms:2ms}, {@code tcp/HOST:PORT})
     * stays on one line: picocli's wrapping breaks after such punctuation ({@code https:} /
     * {@code //ui.perfetto.dev}), so these words must sit where no line ends. The synopsis is
     * abbreviated ({@code [OPTIONS]}) for the same reason.
     */
    @Test
    void noWordIsSplitAcrossLines() {
        for (CommandLine c : commands()) {
            CommandSpec spec = c.getCommandSpec();
            CommandLine.Help help = c.getHelp();
            assertWhole(spec, String.join(" ", spec.usageMessage().description()), help.description());
            assertWhole(spec, String.join(" ", spec.usageMessage().footer()), help.footer());
            for (OptionSpec o : spec.options()) { // the options' own rows: an example elsewhere does not count
                String text = String.join(" ", o.description()).replace("${DEFAULT-VALUE}", String.valueOf(o.defaultValue()));
                assertWhole(spec, text + (o.arity().max > 0 ? " " + o.longestName() + "=" + o.paramLabel() : ""),
                        help.optionList());
            }
            for (String line : spec.usageMessage().description()) {
                assertTrue(!line.startsWith("  ") || line.length() < 80, spec.qualifiedName()
                        + ": an example wider than the help wraps into the next line: " + line);
            }
        }
    }

    private static void assertWhole(CommandSpec spec, String text, String rendered) {
        for (String w : text.split("\\s+")) {
            String word = w.replaceAll("^[(\"']+|[).,;:\"']+$", "");
            if (word.matches(".*\\w[:/.]+[\\w+].*")) {
                assertTrue(rendered.contains(word), spec.qualifiedName() + " --help splits '" + word + "':\n" + rendered);
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
