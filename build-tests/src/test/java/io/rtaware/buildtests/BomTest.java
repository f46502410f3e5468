package io.rtaware.buildtests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import org.w3c.dom.Node;

/**
 * {@code io.rtaware:rtaware-bom} lists every library module of the build at the project's version,
 * and nothing else: the parent pom's modules except the command line, the benchmarks, the examples,
 * the build's tests, the archetype and the BOM itself. A module added to the build without its line
 * in the BOM fails here.
 */
class BomTest {

    private static final Set<String> NOT_LIBRARIES = Set.of("rtaware-app", "rtaware-bench", "rtaware-examples",
            "rtaware-build-tests", "rtaware-archetype", "rtaware-bom");

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
}
