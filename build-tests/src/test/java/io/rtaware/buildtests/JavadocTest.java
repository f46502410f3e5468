package io.rtaware.buildtests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every module's {@code package}, and so {@code verify}, builds its Javadoc with doclint, every
 * warning an error, into a {@code -javadoc} jar beside a {@code -sources} jar: shown on a fixture
 * under the project's parent pom whose one public method has no Javadoc, and on the same fixture
 * documented.
 */
class JavadocTest {

    @TempDir
    Path dir;

    private Fixture.Result packageFixture(String limitDoc) throws Exception {
        Fixture fixture = new Fixture(dir);
        fixture.write("pom.xml", fixture.parentedPom("", "javadoc-fixture", "jar", ""));
        fixture.write("src/main/java/fixture/Speed.java", """
                package fixture;

                /** The speed a robot may drive at. */
                public final class Speed {
                    private Speed() {
                    }

                %s    public static double limitMps() {
                        return 0.3;
                    }
                }
                """.formatted(limitDoc));
        return fixture.maven("package", "-DskipTests");
    }

    @Test
    void aPublicMethodWithoutJavadocFailsPackage() throws Exception {
        Fixture.Result result = packageFixture("");

        assertNotEquals(0, result.status(), "the build fails:\n" + result.output());
        assertTrue(result.output().contains("Speed.java:8: warning: no comment"),
                "doclint names the file, the line and the problem:\n" + result.output());
    }

    @Test
    void documentedPackagesWithJavadocAndSourcesJars() throws Exception {
        Fixture.Result result = packageFixture("    /** @return the limit, m/s */\n");

        assertEquals(0, result.status(), "the control passes, so the failure above is doclint's:\n" + result.output());
        assertTrue(Files.isRegularFile(dir.resolve("target/javadoc-fixture-0.1.0-SNAPSHOT-javadoc.jar")), "a -javadoc jar");
        assertTrue(Files.isRegularFile(dir.resolve("target/javadoc-fixture-0.1.0-SNAPSHOT-sources.jar")), "a -sources jar");
    }
}
