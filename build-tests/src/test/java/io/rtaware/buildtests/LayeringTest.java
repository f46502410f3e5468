package io.rtaware.buildtests;

import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The build refuses what docs/ARCHITECTURE.md forbids: Maven, run offline through the project's
 * wrapper on fixture projects whose parent is the project's own parent pom (and, for layering,
 * whose modules are copies of the real modules' poms), fails on a dependency that points up and
 * on a dependency used but not declared or declared but not used. Nothing is installed: the
 * fixtures live in a temporary folder and build no further than they must.
 */
class LayeringTest {

    private static final Path ROOT = projectRoot();

    @TempDir
    Path dir;

    private static Path projectRoot() {
        Path root = Path.of("").toAbsolutePath().getParent();
        if (!Files.isRegularFile(root.resolve("mvnw")) || !Files.isRegularFile(root.resolve("rtaware-core/pom.xml"))) {
            throw new IllegalStateException("not run from a module of the rtaware project: " + root);
        }
        return root;
    }

    /** A real module's pom, its parent found at the project's parent pom from the fixture. */
    private String realPom(String module) throws IOException {
        String pom = Files.readString(ROOT.resolve(module).resolve("pom.xml"), StandardCharsets.UTF_8);
        String parentEnd = "    <version>0.1.0-SNAPSHOT</version>\n  </parent>";
        assertTrue(pom.contains(parentEnd), module + "'s pom names its parent as expected");
        return pom.replace(parentEnd, "    <version>0.1.0-SNAPSHOT</version>\n    <relativePath>"
                + parentPath(module) + "</relativePath>\n  </parent>");
    }

    private static String withDependency(String pom, String groupId, String artifactId) {
        return pom.replaceFirst("  <dependencies>\n", "  <dependencies>\n    <dependency>\n      <groupId>" + groupId
                + "</groupId>\n      <artifactId>" + artifactId + "</artifactId>\n    </dependency>\n");
    }

    /** Maven reads a relative path only: from the fixture's folder {@code at} to the project's parent pom. */
    private String parentPath(String at) {
        return dir.resolve(at).relativize(ROOT.resolve("pom.xml")).toString();
    }

    private String parentedPom(String at, String artifactId, String packaging, String body) {
        return """
                <?xml version="1.0" encoding="UTF-8"?>
                <project xmlns="http://maven.apache.org/POM/4.0.0">
                  <modelVersion>4.0.0</modelVersion>
                  <parent>
                    <groupId>io.rtaware</groupId>
                    <artifactId>rtaware-parent</artifactId>
                    <version>0.1.0-SNAPSHOT</version>
                    <relativePath>%s</relativePath>
                  </parent>
                  <artifactId>%s</artifactId>
                  <packaging>%s</packaging>
                %s</project>
                """.formatted(parentPath(at), artifactId, packaging, body);
    }

    private void write(String relative, String text) throws IOException {
        Path file = dir.resolve(relative);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text, StandardCharsets.UTF_8);
    }

    /** Runs the wrapper offline on the fixture; returns its exit status and output. */
    private Result maven(String... goals) throws Exception {
        Path log = dir.resolve("maven.log");
        List<String> command = new ArrayList<>(List.of(ROOT.resolve("mvnw").toString(), "-B", "-o",
                "-f", dir.resolve("pom.xml").toString()));
        command.addAll(List.of(goals));
        ProcessBuilder builder = new ProcessBuilder(command).directory(ROOT.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        // A short-lived Maven starts faster without the optimizing compiler.
        builder.environment().put("MAVEN_OPTS", "-XX:TieredStopAtLevel=1");
        Process process = builder.start();
        assertTrue(process.waitFor(5, TimeUnit.MINUTES), "Maven finished");
        return new Result(process.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
    }

    private record Result(int status, String output) {
    }

    @Test
    void aModuleThatDependsOnAModuleAboveItFailsTheBuild() throws Exception {
        // The real core and robot poms; nav a stub above robot. Robot, which may use core only, asks for nav.
        write("pom.xml", parentedPom("", "layering-fixture", "pom",
                "  <modules>\n    <module>rtaware-core</module>\n    <module>rtaware-nav</module>\n"
                        + "    <module>rtaware-robot</module>\n  </modules>\n"));
        write("rtaware-core/pom.xml", realPom("rtaware-core"));
        write("rtaware-nav/pom.xml", parentedPom("rtaware-nav", "rtaware-nav", "jar", ""));
        write("rtaware-robot/pom.xml", withDependency(realPom("rtaware-robot"), "io.rtaware", "rtaware-nav"));

        Result result = maven("validate");

        assertNotEquals(0, result.status(), "the build fails:\n" + result.output());
        assertTrue(result.output().contains("an arrow pointing up: rtaware-robot may depend only on the modules below it"),
                "the layering rule names the module:\n" + result.output());
        assertTrue(result.output().contains("io.rtaware:rtaware-nav"), "and the dependency:\n" + result.output());
    }

    @Test
    void theRealPomsOfCoreAndRobotPassTheSameCheck() throws Exception {
        write("pom.xml", parentedPom("", "layering-fixture", "pom",
                "  <modules>\n    <module>rtaware-core</module>\n    <module>rtaware-robot</module>\n  </modules>\n"));
        write("rtaware-core/pom.xml", realPom("rtaware-core"));
        write("rtaware-robot/pom.xml", realPom("rtaware-robot"));

        Result result = maven("validate");

        assertTrue(result.status() == 0, "the control passes, so the failure above is the rule's:\n" + result.output());
    }

    @Test
    void theFoxgloveServerMayNotReachTheLiveViewAboveTheRecorder() throws Exception {
        // The real foxglove pom (foxglove -> record only); record and live stubs. Foxglove asks for live.
        write("pom.xml", parentedPom("", "layering-fixture", "pom",
                "  <modules>\n    <module>rtaware-record</module>\n    <module>rtaware-live</module>\n"
                        + "    <module>rtaware-foxglove</module>\n  </modules>\n"));
        write("rtaware-record/pom.xml", parentedPom("rtaware-record", "rtaware-record", "jar", ""));
        write("rtaware-live/pom.xml", parentedPom("rtaware-live", "rtaware-live", "jar", ""));
        write("rtaware-foxglove/pom.xml", withDependency(realPom("rtaware-foxglove"), "io.rtaware", "rtaware-live"));

        Result result = maven("validate");

        assertNotEquals(0, result.status(), "the build fails:\n" + result.output());
        assertTrue(result.output().contains("an arrow pointing up: rtaware-foxglove may depend only on the modules below it"),
                "the layering rule names the module:\n" + result.output());
        assertTrue(result.output().contains("io.rtaware:rtaware-live"), "and the dependency:\n" + result.output());
    }

    @Test
    void aDependencyUsedButNotDeclaredOrDeclaredButNotUsedFailsTheBuild() throws Exception {
        // Declares databind and HdrHistogram; uses jackson-core (only transitive) and not HdrHistogram.
        write("pom.xml", parentedPom("", "undeclared-fixture", "jar", """
                  <dependencies>
                    <dependency>
                      <groupId>com.fasterxml.jackson.core</groupId>
                      <artifactId>jackson-databind</artifactId>
                    </dependency>
                    <dependency>
                      <groupId>org.hdrhistogram</groupId>
                      <artifactId>HdrHistogram</artifactId>
                    </dependency>
                  </dependencies>
                """));
        write("src/main/java/fixture/Parse.java", """
                package fixture;

                import com.fasterxml.jackson.core.JsonFactory;
                import com.fasterxml.jackson.databind.ObjectMapper;

                /** Uses databind, declared, and jackson-core, not declared. */
                public final class Parse {
                    private Parse() {
                    }

                    /** @return a mapper on a factory */
                    public static ObjectMapper mapper() {
                        return new ObjectMapper(new JsonFactory());
                    }
                }
                """);

        Result result = maven("process-test-classes");

        assertNotEquals(0, result.status(), "the build fails:\n" + result.output());
        assertTrue(result.output().contains("Used undeclared dependencies found")
                && result.output().contains("com.fasterxml.jackson.core:jackson-core"),
                "the undeclared dependency is named:\n" + result.output());
        assertTrue(result.output().contains("Unused declared dependencies found")
                && result.output().contains("org.hdrhistogram:HdrHistogram"),
                "the unused dependency is named:\n" + result.output());
    }
}
