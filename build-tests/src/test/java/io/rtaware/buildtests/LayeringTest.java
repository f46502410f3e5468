package io.rtaware.buildtests;

import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
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

    @TempDir
    Path dir;

    private Fixture fixture;

    @BeforeEach
    void fixture() {
        fixture = new Fixture(dir);
    }

    private static String withDependency(String pom, String groupId, String artifactId) {
        return pom.replaceFirst("  <dependencies>\n", "  <dependencies>\n    <dependency>\n      <groupId>" + groupId
                + "</groupId>\n      <artifactId>" + artifactId + "</artifactId>\n    </dependency>\n");
    }

    @Test
    void aModuleThatDependsOnAModuleAboveItFailsTheBuild() throws Exception {
        // The real core and robot poms; nav a stub above robot. Robot, which may use core only, asks for nav.
        fixture.write("pom.xml", fixture.parentedPom("", "layering-fixture", "pom",
                "  <modules>\n    <module>rtaware-core</module>\n    <module>rtaware-nav</module>\n"
                        + "    <module>rtaware-robot</module>\n  </modules>\n"));
        fixture.write("rtaware-core/pom.xml", fixture.realPom("rtaware-core"));
        fixture.write("rtaware-nav/pom.xml", fixture.parentedPom("rtaware-nav", "rtaware-nav", "jar", ""));
        fixture.write("rtaware-robot/pom.xml", withDependency(fixture.realPom("rtaware-robot"), "io.rtaware", "rtaware-nav"));

        Fixture.Result result = fixture.maven("validate");

        assertNotEquals(0, result.status(), "the build fails:\n" + result.output());
        assertTrue(result.output().contains("an arrow pointing up: rtaware-robot may depend only on the modules below it"),
                "the layering rule names the module:\n" + result.output());
        assertTrue(result.output().contains("io.rtaware:rtaware-nav"), "and the dependency:\n" + result.output());
    }

    @Test
    void theRealPomsOfCoreAndRobotPassTheSameCheck() throws Exception {
        fixture.write("pom.xml", fixture.parentedPom("", "layering-fixture", "pom",
                "  <modules>\n    <module>rtaware-core</module>\n    <module>rtaware-robot</module>\n  </modules>\n"));
        fixture.write("rtaware-core/pom.xml", fixture.realPom("rtaware-core"));
        fixture.write("rtaware-robot/pom.xml", fixture.realPom("rtaware-robot"));

        Fixture.Result result = fixture.maven("validate");

        assertTrue(result.status() == 0, "the control passes, so the failure above is the rule's:\n" + result.output());
    }

    @Test
    void theFoxgloveServerMayNotReachTheLiveViewAboveTheRecorder() throws Exception {
        // The real foxglove pom (foxglove -> record only); record and live stubs. Foxglove asks for live.
        fixture.write("pom.xml", fixture.parentedPom("", "layering-fixture", "pom",
                "  <modules>\n    <module>rtaware-record</module>\n    <module>rtaware-live</module>\n"
                        + "    <module>rtaware-foxglove</module>\n  </modules>\n"));
        fixture.write("rtaware-record/pom.xml", fixture.parentedPom("rtaware-record", "rtaware-record", "jar", ""));
        fixture.write("rtaware-live/pom.xml", fixture.parentedPom("rtaware-live", "rtaware-live", "jar", ""));
        fixture.write("rtaware-foxglove/pom.xml", withDependency(fixture.realPom("rtaware-foxglove"), "io.rtaware", "rtaware-live"));

        Fixture.Result result = fixture.maven("validate");

        assertNotEquals(0, result.status(), "the build fails:\n" + result.output());
        assertTrue(result.output().contains("an arrow pointing up: rtaware-foxglove may depend only on the modules below it"),
                "the layering rule names the module:\n" + result.output());
        assertTrue(result.output().contains("io.rtaware:rtaware-live"), "and the dependency:\n" + result.output());
    }

    @Test
    void aDependencyUsedButNotDeclaredOrDeclaredButNotUsedFailsTheBuild() throws Exception {
        // Declares databind and HdrHistogram; uses jackson-core (only transitive) and not HdrHistogram.
        fixture.write("pom.xml", fixture.parentedPom("", "undeclared-fixture", "jar", """
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
        fixture.write("src/main/java/fixture/Parse.java", """
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

        Fixture.Result result = fixture.maven("process-test-classes");

        assertNotEquals(0, result.status(), "the build fails:\n" + result.output());
        assertTrue(result.output().contains("Used undeclared dependencies found")
                && result.output().contains("com.fasterxml.jackson.core:jackson-core"),
                "the undeclared dependency is named:\n" + result.output());
        assertTrue(result.output().contains("Unused declared dependencies found")
                && result.output().contains("org.hdrhistogram:HdrHistogram"),
                "the unused dependency is named:\n" + result.output());
    }
}
