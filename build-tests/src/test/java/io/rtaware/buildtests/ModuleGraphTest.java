package io.rtaware.buildtests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * The module graph is written in one place, docs/ARCHITECTURE.md's "Module graph" block (each
 * module in build order, bottom up, with the modules it depends on), and the poms agree with it:
 * the parent's {@code <modules>} lists the same modules in the same order, every module's project
 * dependencies (any scope) are exactly its arrows, its enforcer {@code layering} list (what the
 * build lets it depend on) is exactly its arrows too, and every arrow points to a module listed
 * before it. Read from the files of the working tree; nothing is built.
 */
class ModuleGraphTest {

    /** The line before the block in docs/ARCHITECTURE.md. */
    static final String MARKER = "<!-- module graph: build-tests' ModuleGraphTest checks it against the poms -->";
    private static final String GROUP = "io.rtaware";
    private static final String PREFIX = "rtaware-";

    private static final Path ROOT = projectRoot();

    private static Path projectRoot() {
        Path root = Path.of("").toAbsolutePath().getParent();
        if (!Files.isRegularFile(root.resolve("docs/ARCHITECTURE.md")) || !Files.isRegularFile(root.resolve("pom.xml"))) {
            throw new IllegalStateException("not run from a module of the rtaware project: " + root);
        }
        return root;
    }

    /**
     * What a module's pom says.
     *
     * @param dependencies its project dependencies, by short name
     * @param layering its enforcer {@code layering} includes, by short name
     */
    record Pom(Set<String> dependencies, Set<String> layering) {
    }

    @Test
    void theDocumentedGraphIsThePoms() throws Exception {
        Map<String, Set<String>> documented = documentedGraph(
                Files.readString(ROOT.resolve("docs/ARCHITECTURE.md"), StandardCharsets.UTF_8));
        List<String> order = parentModules();
        Map<String, Pom> poms = new LinkedHashMap<>();
        for (String module : order) {
            poms.put(module, pom(module));
        }

        List<String> problems = differences(documented, order, poms);

        assertEquals(List.of(), problems, "docs/ARCHITECTURE.md's module graph and the poms differ");
        assertTrue(documented.get("app").containsAll(List.of("ros2", "zenoh", "ros2msg")),
                "app's arrows to ros2, zenoh and ros2msg are written: " + documented.get("app"));
    }

    @Test
    void anArrowMissingFromTheDocumentOrAnUpwardOneIsNamed() {
        List<String> order = List.of("core", "robot", "nav", "app");
        Map<String, Pom> poms = new LinkedHashMap<>();
        poms.put("core", new Pom(Set.of(), Set.of()));
        poms.put("robot", new Pom(Set.of("core"), Set.of("core")));
        poms.put("nav", new Pom(Set.of("core", "robot"), Set.of("core", "robot", "app")));
        poms.put("app", new Pom(Set.of("core", "robot", "nav"), Set.of("core", "robot", "nav")));
        Map<String, Set<String>> documented = documentedGraph("""
                text before
                %s
                ```text
                core  ->
                robot -> core
                nav   -> core, robot, app
                app   -> core, nav
                ```
                """.formatted(MARKER));

        List<String> problems = differences(documented, order, poms);

        assertTrue(problems.contains("app: the pom depends on [robot], which the document does not show"), problems.toString());
        assertTrue(problems.contains("nav: the document shows [app], on which the pom does not depend"), problems.toString());
        assertTrue(problems.contains("nav: an arrow to app, which is not below it"), problems.toString());
        assertFalse(problems.stream().anyMatch(p -> p.startsWith("robot")), problems.toString());
    }

    @Test
    void modulesInAnotherOrderThanTheParentsAreNamed() {
        Map<String, Set<String>> documented = documentedGraph(MARKER + "\n```text\nrobot -> core\ncore ->\n```\n");
        Map<String, Pom> poms = Map.of("core", new Pom(Set.of(), Set.of()), "robot", new Pom(Set.of("core"), Set.of("core")));

        List<String> problems = differences(documented, List.of("core", "robot"), poms);

        assertTrue(problems.contains("the document lists the modules as [robot, core], the parent pom as [core, robot]"),
                problems.toString());
    }

    /**
     * @param documented the document's graph, in its order
     * @param order the parent pom's modules, in order
     * @param poms each module's pom
     * @return one sentence per difference; empty when they agree
     */
    static List<String> differences(Map<String, Set<String>> documented, List<String> order, Map<String, Pom> poms) {
        List<String> problems = new ArrayList<>();
        if (!new ArrayList<>(documented.keySet()).equals(order)) {
            problems.add("the document lists the modules as " + documented.keySet() + ", the parent pom as " + order);
        }
        for (String module : order) {
            Set<String> arrows = documented.getOrDefault(module, Set.of());
            Pom pom = poms.get(module);
            Set<String> undocumented = minus(pom.dependencies(), arrows);
            if (!undocumented.isEmpty()) {
                problems.add(module + ": the pom depends on " + undocumented + ", which the document does not show");
            }
            Set<String> unused = minus(arrows, pom.dependencies());
            if (!unused.isEmpty()) {
                problems.add(module + ": the document shows " + unused + ", on which the pom does not depend");
            }
            if (!pom.layering().equals(arrows)) {
                problems.add(module + ": the layering rule allows " + new TreeSet<>(pom.layering())
                        + ", the document " + new TreeSet<>(arrows));
            }
            for (String target : arrows) {
                int at = order.indexOf(target);
                if (at < 0 || at >= order.indexOf(module)) {
                    problems.add(module + ": an arrow to " + target + ", which is not below it");
                }
            }
        }
        return problems;
    }

    private static Set<String> minus(Set<String> a, Set<String> b) {
        Set<String> out = new TreeSet<>(a);
        out.removeAll(b);
        return out;
    }

    /**
     * @param markdown the architecture document
     * @return the fenced block after {@link #MARKER}: per line {@code module -> dep, dep}, in order
     */
    static Map<String, Set<String>> documentedGraph(String markdown) {
        List<String> lines = markdown.lines().toList();
        int at = lines.indexOf(MARKER);
        if (at < 0 || at + 1 >= lines.size() || !lines.get(at + 1).startsWith("```")) {
            throw new IllegalArgumentException("no fenced block after the line " + MARKER);
        }
        Map<String, Set<String>> graph = new LinkedHashMap<>();
        for (int i = at + 2; i < lines.size() && !lines.get(i).startsWith("```"); i++) {
            String[] sides = lines.get(i).split("->", -1);
            if (sides.length != 2 || sides[0].isBlank()) {
                throw new IllegalArgumentException("not 'module -> module, module': " + lines.get(i));
            }
            Set<String> targets = new LinkedHashSet<>();
            for (String target : sides[1].split(",")) {
                if (!target.isBlank()) {
                    targets.add(target.trim());
                }
            }
            graph.put(sides[0].trim(), targets);
        }
        return graph;
    }

    /** @return the parent pom's modules, by short name, in its order */
    private static List<String> parentModules() throws Exception {
        List<String> modules = new ArrayList<>();
        NodeList list = xml(ROOT.resolve("pom.xml")).getElementsByTagName("module");
        for (int i = 0; i < list.getLength(); i++) {
            modules.add(shortName(list.item(i).getTextContent().trim()));
        }
        return modules;
    }

    private static Pom pom(String module) throws Exception {
        Path dir = Files.isDirectory(ROOT.resolve(PREFIX + module)) ? ROOT.resolve(PREFIX + module) : ROOT.resolve(module);
        Element project = xml(dir.resolve("pom.xml")).getDocumentElement();
        Set<String> dependencies = new TreeSet<>();
        Element deps = child(project, "dependencies");
        if (deps != null) {
            for (Element d : children(deps, "dependency")) {
                if (GROUP.equals(text(d, "groupId"))) {
                    dependencies.add(shortName(text(d, "artifactId")));
                }
            }
        }
        Set<String> layering = new TreeSet<>();
        NodeList includes = project.getElementsByTagName("include");
        for (int i = 0; i < includes.getLength(); i++) {
            String include = includes.item(i).getTextContent().trim();
            if (include.startsWith(GROUP + ":")) {
                layering.add(shortName(include.substring(GROUP.length() + 1)));
            }
        }
        return new Pom(dependencies, layering);
    }

    private static String shortName(String artifactOrFolder) {
        return artifactOrFolder.startsWith(PREFIX) ? artifactOrFolder.substring(PREFIX.length()) : artifactOrFolder;
    }

    private static Document xml(Path file) throws Exception {
        try {
            return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile());
        } catch (IOException e) {
            throw new IOException("cannot read " + file + ": " + e.getMessage(), e);
        }
    }

    private static Element child(Element parent, String name) {
        List<Element> found = children(parent, name);
        return found.isEmpty() ? null : found.get(0);
    }

    private static List<Element> children(Element parent, String name) {
        List<Element> out = new ArrayList<>();
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(name)) {
                out.add(e);
            }
        }
        return out;
    }

    private static String text(Element parent, String name) {
        Element e = child(parent, name);
        return e == null ? null : e.getTextContent().trim();
    }
}
