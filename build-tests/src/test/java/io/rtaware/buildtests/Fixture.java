package io.rtaware.buildtests;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A tiny Maven project in a temporary folder whose parent is the project's own parent pom, built
 * offline through the project's wrapper. Nothing is installed: fixtures build no further than they
 * must.
 */
final class Fixture {

    /** The project's root folder (the tests run in {@code build-tests}). */
    static final Path ROOT = projectRoot();

    private final Path dir;

    /** @param dir the fixture's folder, empty */
    Fixture(Path dir) {
        this.dir = dir;
    }

    private static Path projectRoot() {
        Path root = Path.of("").toAbsolutePath().getParent();
        if (!Files.isRegularFile(root.resolve("mvnw")) || !Files.isRegularFile(root.resolve("rtaware-core/pom.xml"))) {
            throw new IllegalStateException("not run from a module of the rtaware project: " + root);
        }
        return root;
    }

    /** A real module's pom, its parent found at the project's parent pom from the fixture. */
    String realPom(String module) throws IOException {
        String pom = Files.readString(ROOT.resolve(module).resolve("pom.xml"), StandardCharsets.UTF_8);
        String parentEnd = "    <version>0.1.0-SNAPSHOT</version>\n  </parent>";
        assertTrue(pom.contains(parentEnd), module + "'s pom names its parent as expected");
        return pom.replace(parentEnd, "    <version>0.1.0-SNAPSHOT</version>\n    <relativePath>"
                + parentPath(module) + "</relativePath>\n  </parent>");
    }

    /** Maven reads a relative path only: from the fixture's folder {@code at} to the project's parent pom. */
    private String parentPath(String at) {
        return dir.resolve(at).relativize(ROOT.resolve("pom.xml")).toString();
    }

    /** A pom at {@code at} (relative to the fixture) whose parent is the project's parent pom. */
    String parentedPom(String at, String artifactId, String packaging, String body) {
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

    void write(String relative, String text) throws IOException {
        Path file = dir.resolve(relative);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text, StandardCharsets.UTF_8);
    }

    /** Runs the wrapper offline on the fixture; returns its exit status and output. */
    Result maven(String... goals) throws Exception {
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

    /**
     * @param status Maven's exit status
     * @param output what it printed
     */
    record Result(int status, String output) {
    }
}
