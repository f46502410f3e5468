package io.rtaware.experiment.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;

/**
 * A report as a list of blocks (headings, paragraphs, tables, figures), rendered once as
 * Markdown and once as a standalone HTML page with the figures inline, so both say the same.
 */
final class Blocks {

    /** A part of the report. */
    sealed interface Block permits Heading, Text, Table, Figure {
    }

    /**
     * @param level 1 to 3
     * @param text the heading
     */
    record Heading(int level, String text) implements Block {
    }

    /** @param text a paragraph (Markdown {@code **bold**} and {@code `code`} are rendered in HTML too) */
    record Text(String text) implements Block {
    }

    /**
     * @param header column names
     * @param rows cells, one list per row
     */
    record Table(List<String> header, List<List<String>> rows) implements Block {
    }

    /**
     * @param file the PNG's file name in the report folder
     * @param caption what it shows
     */
    record Figure(String file, String caption) implements Block {
    }

    private final List<Block> blocks = new ArrayList<>();

    Blocks heading(int level, String text) {
        blocks.add(new Heading(level, text));
        return this;
    }

    Blocks text(String text) {
        blocks.add(new Text(text));
        return this;
    }

    Blocks table(List<String> header, List<List<String>> rows) {
        blocks.add(new Table(header, rows));
        return this;
    }

    Blocks figure(String file, String caption) {
        blocks.add(new Figure(file, caption));
        return this;
    }

    String markdown() {
        StringBuilder md = new StringBuilder();
        for (Block b : blocks) {
            if (b instanceof Heading h) {
                md.append("#".repeat(h.level())).append(' ').append(h.text()).append("\n\n");
            } else if (b instanceof Text t) {
                md.append(t.text()).append("\n\n");
            } else if (b instanceof Table t) {
                md.append("| ").append(String.join(" | ", t.header())).append(" |\n|");
                t.header().forEach(c -> md.append(" --- |"));
                md.append('\n');
                t.rows().forEach(r -> md.append("| ").append(String.join(" | ", r)).append(" |\n"));
                md.append('\n');
            } else if (b instanceof Figure f) {
                md.append("![").append(f.caption()).append("](").append(f.file()).append(")\n\n");
            }
        }
        return md.toString();
    }

    String html(String title, Path dir) throws IOException {
        StringBuilder h = new StringBuilder();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>").append(escape(title))
                .append("</title>\n<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}"
                        + "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}"
                        + "th{background:#f4f4f4}td:first-child,th:first-child{text-align:left}img{max-width:100%}"
                        + "figure{margin:1em 0}figcaption{color:#555}code{background:#f4f4f4;padding:0 3px}</style>\n</head><body>\n");
        for (Block b : blocks) {
            if (b instanceof Heading hd) {
                h.append("<h").append(hd.level()).append('>').append(inline(hd.text())).append("</h").append(hd.level()).append(">\n");
            } else if (b instanceof Text t) {
                h.append("<p>").append(inline(t.text())).append("</p>\n");
            } else if (b instanceof Table t) {
                h.append("<table>\n<tr>");
                t.header().forEach(c -> h.append("<th>").append(inline(c)).append("</th>"));
                h.append("</tr>\n");
                for (List<String> r : t.rows()) {
                    h.append("<tr>");
                    r.forEach(c -> h.append("<td>").append(inline(c)).append("</td>"));
                    h.append("</tr>\n");
                }
                h.append("</table>\n");
            } else if (b instanceof Figure f) {
                Path png = dir.resolve(f.file());
                String src = Files.exists(png)
                        ? "data:image/png;base64," + Base64.getEncoder().encodeToString(Files.readAllBytes(png))
                        : f.file();
                h.append("<figure><img src=\"").append(src).append("\" alt=\"").append(escape(f.caption()))
                        .append("\"><figcaption>").append(inline(f.caption())).append("</figcaption></figure>\n");
            }
        }
        return h.append("</body></html>\n").toString();
    }

    private static String inline(String text) {
        String s = escape(text);
        s = s.replaceAll("\\*\\*([^*]+)\\*\\*", "<b>$1</b>");
        return s.replaceAll("`([^`]+)`", "<code>$1</code>");
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
