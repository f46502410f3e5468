package io.rtaware.experiment.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Every verdict the docs state about a claim of the paper, in the form
 * {@code claim `FOLDER/ID`: VERDICT}, or about one of rtaware's own rules, {@code rule `FOLDER/ID`:
 * VERDICT} (as {@link ResultsMarkdown} writes them, and as README.md and docs/ quote them), is the
 * verdict in {@code docs/experiment/FOLDER/summary.json}. A verdict
 * written by hand that the results do not give, or results regenerated without the docs, fail
 * here.
 */
class DocsVerdictsTest {

    /** The greppable form of a verdict statement in the docs. */
    static final Pattern STATEMENT = Pattern.compile(
            "(?:claim|rule) `([A-Za-z0-9_.-]+)/([A-Za-z0-9_.@-]+)`: \\**(reproduced|not_reproduced|mixed|inconclusive"
                    + "|not_comparable|not_evaluated|holds|fails)\\b");

    private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();

    @Test
    void everyVerdictQuotedInTheDocsIsTheOneInItsSummary() throws IOException {
        List<Path> docs = new ArrayList<>();
        if (Files.exists(ROOT.resolve("README.md"))) {
            docs.add(ROOT.resolve("README.md"));
        }
        try (Stream<Path> files = Files.walk(ROOT.resolve("docs"))) {
            files.filter(p -> p.toString().endsWith(".md")).forEach(docs::add);
        }
        Map<String, Map<String, String>> summaries = new HashMap<>();
        List<String> wrong = new ArrayList<>();
        int checked = 0;
        for (Path doc : docs) {
            List<String> lines = Files.readAllLines(doc);
            for (int i = 0; i < lines.size(); i++) {
                Matcher m = STATEMENT.matcher(lines.get(i));
                while (m.find()) {
                    checked++;
                    Map<String, String> verdicts = summaries.computeIfAbsent(m.group(1), DocsVerdictsTest::verdicts);
                    String actual = verdicts.get(m.group(2));
                    if (!m.group(3).equals(actual)) {
                        wrong.add(ROOT.relativize(doc) + ":" + (i + 1) + " says claim " + m.group(1) + "/" + m.group(2)
                                + " is " + m.group(3) + "; docs/experiment/" + m.group(1) + "/summary.json says "
                                + (actual == null ? "no such claim" : actual));
                    }
                }
            }
        }
        assertTrue(checked > 0, "the docs quote at least one verdict (docs/experiment/RESULTS.md does)");
        assertEquals(List.of(), wrong, "verdicts in the docs that their summary.json does not give; regenerate with "
                + "rtaware report --results docs/experiment/RESULTS.md ... and quote it");
    }

    @Test
    void theFormMatchesWhatResultsMarkdownWrites() {
        assertTrue(STATEMENT.matcher("- claim `paper-profile/slow-hits@0.5mps`: not_reproduced. Paper: ...").find());
        assertTrue(STATEMENT.matcher("the Set 1 claim is claim `paper-profile/table1-set1-faster`: **mixed**").find());
        assertTrue(STATEMENT.matcher("- rule `office-obstacle/reaction-rule-bound-on-office`: not_evaluated. Rule: ...")
                .find());
    }

    /** @return claim id to verdict, from a folder's summary.json (not evaluated ones as {@code not_evaluated}) */
    private static Map<String, String> verdicts(String folder) {
        Path file = ROOT.resolve("docs/experiment").resolve(folder).resolve(ExperimentReport.SUMMARY_FILE);
        Map<String, String> out = new HashMap<>();
        if (!Files.exists(file)) {
            return out;
        }
        try {
            JsonNode root = new ObjectMapper().readTree(file.toFile());
            root.path("claims").forEach(c -> out.put(c.path("id").asText(), c.path("verdict").asText()));
            root.path("claims_not_evaluated").forEach(c -> out.put(c.path("id").asText(), ResultsMarkdown.NOT_EVALUATED));
            root.path("rules").forEach(r -> out.put(r.path("id").asText(), r.path("verdict").asText()));
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        return out;
    }
}
