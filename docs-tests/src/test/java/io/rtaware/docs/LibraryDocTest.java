package io.rtaware.docs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * docs/library.md's code, read from the page and compiled as the page shows it, against the
 * library, every lint warning on. The page's imports block (a block of import lines only) heads
 * every other block; a whole file (from its package declaration on) is compiled as it is; any
 * other block is the body of a static method that may throw anything, whose parameters are what
 * the comment {@code <!-- given: Type name, ... -->} on the line before the block declares (the
 * variables the page's text names). A problem is reported at its line of the page.
 */
class LibraryDocTest {

    private static final Path PAGE = Path.of("../docs/library.md");

    @TempDir
    Path dir;

    @Test
    void everyJavaBlockOfTheLibraryGuideCompiles() throws IOException {
        assertEquals(List.of(), problems(PAGE, dir), "docs/library.md's java blocks compile as the page shows them");
        assertTrue(JavaBlock.of(PAGE).size() >= 10, "the page's blocks were found: " + JavaBlock.of(PAGE).size());
    }

    /** The checker itself: a block that does not compile is named by its line on the page. */
    @Test
    void aBlockThatDoesNotCompileIsReportedAtItsLineOnThePage() throws IOException {
        Path page = dir.resolve("page.md");
        Files.writeString(page, String.join("\n",
                "# A page",
                "```java",
                "import java.time.Duration;",
                "```",
                "<!-- given: Duration period -->",
                "```java",
                "long ms = period.toMillis();",
                "long wrong = periodNs;",
                "```",
                ""), StandardCharsets.UTF_8);

        List<String> problems = problems(page, Files.createDirectories(dir.resolve("checker")));

        assertEquals(1, problems.size(), "one problem: " + problems);
        assertTrue(problems.get(0).startsWith("page.md:8: error: cannot find symbol"), problems.get(0));
    }

    /**
     * @param page a Markdown page
     * @param root a folder of the test's own
     * @return every compiler error and warning, each at its {@code page:line}; empty when clean
     */
    static List<String> problems(Path page, Path root) throws IOException {
        List<JavaBlock> blocks = JavaBlock.of(page);
        List<JavaBlock> imports = blocks.stream().filter(LibraryDocTest::isImports).toList();
        assertTrue(imports.size() <= 1, page + " has at most one imports block: " + imports);
        String header = imports.isEmpty() ? "" : imports.get(0).code();
        Map<String, String> sources = new LinkedHashMap<>();
        Map<String, JavaBlock> blockOfFile = new LinkedHashMap<>();
        Map<String, Integer> firstCodeLine = new LinkedHashMap<>();
        for (JavaBlock block : blocks) {
            if (isImports(block)) {
                continue;
            }
            if (block.isWholeFile()) {
                String file = group(block, "^package ([\\w.]+);").replace('.', '/') + "/"
                        + group(block, "^public (?:final |abstract )?(?:class|interface|record|enum) (\\w+)") + ".java";
                sources.put(file, block.code());
                blockOfFile.put(Path.of(file).getFileName().toString(), block);
                firstCodeLine.put(Path.of(file).getFileName().toString(), 1);
            } else {
                String name = "Line" + block.line();
                String head = header + "final class " + name + " {\n    static void snippet(" + block.given()
                        + ") throws Exception {\n";
                sources.put(name + ".java", head + block.code() + "    }\n}\n");
                blockOfFile.put(name + ".java", block);
                firstCodeLine.put(name + ".java", (int) head.lines().count() + 1);
            }
        }
        List<String> problems = new ArrayList<>();
        for (UserCompiler.Problem p : UserCompiler.compile(sources, root)) {
            JavaBlock block = blockOfFile.get(p.file());
            problems.add(block == null ? p.toString()
                    : page.getFileName() + ":" + (block.line() + p.line() - firstCodeLine.get(p.file())) + ": " + p.message());
        }
        return problems;
    }

    private static boolean isImports(JavaBlock block) {
        return block.code().lines().map(String::strip).filter(l -> !l.isEmpty() && !l.startsWith("//"))
                .allMatch(l -> l.startsWith("import "));
    }

    private static String group(JavaBlock block, String regex) {
        Matcher m = Pattern.compile(regex, Pattern.MULTILINE).matcher(block.code());
        assertTrue(m.find(), block.where() + ": a whole file has " + regex);
        return m.group(1);
    }
}
