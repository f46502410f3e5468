package io.rtaware.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * README.md and the pages under docs/ stay true to the command line and to each other: every flag
 * they show after {@code rtaware <command>} is an option of that command, every relative link
 * leads to a file (and a {@code #fragment} to a heading of it), and the README stays a front door.
 */
class DocsTest {

    private static final Path ROOT = Path.of("..");
    private static final long README_MAX_BYTES = 12 * 1024;

    /**
     * Linked files that do not exist yet: docs/experiment/RESULTS.md is written by
     * {@code rtaware report} once the published experiment folders are regenerated (issue 26).
     * {@link #pendingLinkTargetsDoNotExistYet()} fails when one appears, so the entry is removed.
     */
    private static final Pattern FENCE = Pattern.compile("```[a-z]*\\n(.*?)```", Pattern.DOTALL);
    private static final Pattern INLINE = Pattern.compile("`([^`]+)`");
    private static final Pattern COMMAND = Pattern.compile(
            "rtaware (run|sim|world|bench|analyze|experiment|report|player-probe|inspect|replay)\\b([^\\n#]*)");
    private static final Pattern FLAG = Pattern.compile("(?<![\\w-])(--[a-z][a-z0-9-]*)");
    private static final Pattern LINK = Pattern.compile("\\]\\(([^)\\s]+)\\)");
    private static final Pattern HEADING = Pattern.compile("^#+\\s+(.*)$", Pattern.MULTILINE);

    @Test
    void everyFlagShownAfterACommandIsAnOptionOfThatCommand() {
        CommandLine cli = new CommandLine(RtawareCli.class);
        List<String> unknown = new ArrayList<>();
        for (Path page : pages()) {
            String text = read(page);
            List<String> code = new ArrayList<>();
            Matcher fence = FENCE.matcher(text);
            while (fence.find()) {
                // a command continued on the next line (a trailing backslash, or a usage line's indented [--flag])
                code.add(fence.group(1).replaceAll("\\\\\\n\\s*", " ").replaceAll("\\n\\s+(?=[\\[-])", " "));
            }
            Matcher inline = INLINE.matcher(FENCE.matcher(text).replaceAll(""));
            while (inline.find()) {
                code.add(inline.group(1).replace('\n', ' '));
            }
            for (String snippet : code) {
                Matcher command = COMMAND.matcher(snippet);
                while (command.find()) {
                    CommandLine.Model.CommandSpec spec = cli.getSubcommands().get(command.group(1)).getCommandSpec();
                    Matcher flag = FLAG.matcher(command.group(2));
                    while (flag.find()) {
                        if (spec.findOption(flag.group(1)) == null) {
                            unknown.add(ROOT.relativize(page) + ": rtaware " + command.group(1) + " " + flag.group(1));
                        }
                    }
                }
            }
        }
        assertEquals(List.of(), unknown, "flags the docs show that the command does not know");
    }

    @Test
    void everyRelativeLinkLeadsToAFileAndItsHeading() {
        List<String> broken = new ArrayList<>();
        for (Path page : pages()) {
            Matcher link = LINK.matcher(FENCE.matcher(read(page)).replaceAll(""));
            while (link.find()) {
                String target = link.group(1);
                if (target.matches("[a-z]+:.*")) {
                    continue;
                }
                int hash = target.indexOf('#');
                String file = hash < 0 ? target : target.substring(0, hash);
                Path resolved = file.isEmpty() ? page : page.getParent().resolve(file).normalize();
                String name = ROOT.relativize(resolved).toString();
                if (!Files.exists(resolved)) {
                    broken.add(ROOT.relativize(page) + ": " + target + " (no file " + name + ")");
                } else if (hash >= 0 && !anchors(resolved).contains(target.substring(hash + 1))) {
                    broken.add(ROOT.relativize(page) + ": " + target + " (no such heading in " + name + ")");
                }
            }
        }
        assertEquals(List.of(), broken, "links in README.md and docs/ that lead nowhere");
    }

    @Test
    void theReadmeIsAFrontDoorOfAtMostTwelveKilobytes() throws IOException {
        long bytes = Files.size(ROOT.resolve("README.md"));
        assertTrue(bytes <= README_MAX_BYTES,
                "README.md is " + bytes + " bytes, more than " + README_MAX_BYTES + ": move detail into docs/");
    }

    private static List<Path> pages() {
        try (Stream<Path> docs = Files.walk(ROOT.resolve("docs"))) {
            List<Path> pages = new ArrayList<>(List.of(ROOT.resolve("README.md")));
            pages.addAll(docs.filter(p -> p.toString().endsWith(".md")).sorted().collect(Collectors.toList()));
            return pages;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** GitHub's anchors of a page's headings: lower case, punctuation dropped, spaces to hyphens. */
    private static Set<String> anchors(Path page) {
        Set<String> anchors = new TreeSet<>();
        Matcher heading = HEADING.matcher(FENCE.matcher(read(page)).replaceAll(""));
        while (heading.find()) {
            anchors.add(heading.group(1).strip().toLowerCase(Locale.ROOT)
                    .replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-'));
        }
        return anchors;
    }

    private static String read(Path page) {
        try {
            return Files.readString(page, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
