package io.rtaware.buildtests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.InputSource;

/**
 * {@code io.rtaware:rtaware-bom} lists every library module of the build at the project's version,
 * and nothing else: the parent pom's modules except the command line, the benchmarks, the examples,
 * the build's tests, the archetype and the BOM itself. A module added to the build without its line
 * in the BOM fails here, and so does docs/getting-started.md's dependency block once it names
 * another BOM or version.
 */
class BomTest {

    private static final Set<String> NOT_LIBRARIES = Set.of("rtaware-app", "rtaware-bench", "rtaware-examples",
            "rtaware-build-tests", "rtaware-docs-tests", "rtaware-archetype", "rtaware-bom");

    private static Element pom(Path file) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile()).getDocumentElement();
    }

    /** The element's children of that name, in order. */
    private static List<Element> children(Element parent, String name) {
        List<Element> found = new ArrayList<>();
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(name)) {
                found.add(e);
            }
        }
        return found;
    }

    /** The text of the element's one child of that name, or null without one. */
    private static String text(Element parent, String name) {
        List<Element> found = children(parent, name);
        return found.isEmpty() ? null : found.get(0).getTextContent().trim();
    }

    private static Element pom(String text) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new InputSource(new StringReader(text))).getDocumentElement();
    }

    @Test
    void theBomListsEveryLibraryModuleAtTheProjectVersion() throws Exception {
        Element parent = pom(Fixture.ROOT.resolve("pom.xml"));
        Set<String> libraries = new TreeSet<>();
        for (Element module : children(children(parent, "modules").get(0), "module")) {
            String artifactId = text(pom(Fixture.ROOT.resolve(module.getTextContent().trim()).resolve("pom.xml")), "artifactId");
            if (!NOT_LIBRARIES.contains(artifactId)) {
                libraries.add(artifactId);
            }
        }
        Element bom = pom(Fixture.ROOT.resolve("rtaware-bom/pom.xml"));
        TreeMap<String, String> managed = new TreeMap<>();
        Element dependencies = children(children(bom, "dependencyManagement").get(0), "dependencies").get(0);
        for (Element dependency : children(dependencies, "dependency")) {
            assertEquals("io.rtaware", text(dependency, "groupId"), "the BOM manages rtaware's modules only");
            managed.put(text(dependency, "artifactId"), text(dependency, "version"));
        }

        assertTrue(children(bom, "parent").isEmpty(), "the BOM inherits nothing, so importing it brings rtaware's versions only");
        assertEquals(text(parent, "version"), text(bom, "version"), "the BOM's version is the project's");
        assertEquals(libraries, managed.keySet(), "the BOM lists every library module and nothing else");
        assertEquals(Set.of("${project.version}"), Set.copyOf(managed.values()), "each at the BOM's own version");
    }

    @Test
    void theGettingStartedPageImportsThisBomAtTheProjectVersion() throws Exception {
        String page = Files.readString(Fixture.ROOT.resolve("docs/getting-started.md"), StandardCharsets.UTF_8);
        Matcher block = Pattern.compile("```xml\n(.*?)```", Pattern.DOTALL).matcher(page);
        assertTrue(block.find(), "docs/getting-started.md has an xml block");
        // the block is a fragment of a pom: its two elements under one root
        Element fragment = pom("<project>" + block.group(1) + "</project>");
        Element imported = children(children(children(fragment, "dependencyManagement").get(0), "dependencies").get(0),
                "dependency").get(0);
        String version = text(pom(Fixture.ROOT.resolve("pom.xml")), "version");

        assertEquals("io.rtaware:rtaware-bom:" + version + ":pom:import", text(imported, "groupId") + ":"
                + text(imported, "artifactId") + ":" + text(imported, "version") + ":" + text(imported, "type") + ":"
                + text(imported, "scope"), "the page imports this BOM");
        Element core = children(children(fragment, "dependencies").get(0), "dependency").get(0);
        assertEquals("rtaware-core", text(core, "artifactId"), "and depends on the core");
        assertNull(text(core, "version"), "without a version: the BOM gives it");
    }
}
