package io.rtaware.docs;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A {@code java} block of a Markdown page, as the page shows it.
 *
 * @param page the page
 * @param line the line of the page where the code starts (from 1)
 * @param heading the nearest heading above it, without its {@code #}s
 * @param given what an HTML comment {@code <!-- given: Type name, ... -->} on the line before the
 *     fence declares the block may use (a method's parameters), or empty
 * @param code the code, each line ending with a newline
 */
record JavaBlock(Path page, int line, String heading, String given, String code) {

    private static final Pattern GIVEN = Pattern.compile("<!--\\s*given:\\s*(.*?)\\s*-->");
    private static final String FENCE = "```";

    /** @return where the block is, as a person looks it up: {@code docs/library.md:42} */
    String where() {
        return page.getFileName() + ":" + line;
    }

    /** @return true if the block is a whole file (it begins with its package declaration) */
    boolean isWholeFile() {
        return code.startsWith("package ");
    }

    /**
     * @param page a Markdown file
     * @return its java blocks, in order
     * @throws IOException if it cannot be read
     * @throws IllegalArgumentException naming the line of a block that is never closed
     */
    static List<JavaBlock> of(Path page) throws IOException {
        List<String> lines = Files.readAllLines(page, StandardCharsets.UTF_8);
        List<JavaBlock> blocks = new ArrayList<>();
        String heading = "";
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.startsWith("#")) {
                heading = line.replaceFirst("^#+\\s*", "");
            } else if (line.startsWith(FENCE)) {
                int end = i + 1;
                while (end < lines.size() && !lines.get(end).startsWith(FENCE)) {
                    end++;
                }
                if (end == lines.size()) {
                    throw new IllegalArgumentException(page + ":" + (i + 1) + ": a code block that is never closed");
                }
                if (line.equals(FENCE + "java")) {
                    StringBuilder code = new StringBuilder();
                    lines.subList(i + 1, end).forEach(l -> code.append(l).append('\n'));
                    Matcher given = GIVEN.matcher(i > 0 ? lines.get(i - 1) : "");
                    blocks.add(new JavaBlock(page, i + 2, heading, given.matches() ? given.group(1) : "", code.toString()));
                }
                i = end;
            }
        }
        return blocks;
    }
}
