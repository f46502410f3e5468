package io.rtaware.core.conditions;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.Optional;
import java.util.Properties;

/**
 * rtaware's version (from the jar's Maven properties) and, when it runs from a git checkout,
 * the commit checked out there (HEAD read from the {@code .git} folder above the code, following
 * a worktree's {@code gitdir:} file and packed refs). Reads only files; runs no program.
 *
 * @param version the version, or {@code unknown} when not run from a built jar
 * @param gitCommit the checkout's HEAD commit, or null when not run from a checkout
 */
public record BuildInfo(String version, String gitCommit) {

    private static final String POM_PROPERTIES = "/META-INF/maven/io.rtaware/rtaware-core/pom.properties";

    /** @return the build this class was loaded from */
    public static BuildInfo ofThisCode() {
        String version = "unknown";
        try (InputStream in = BuildInfo.class.getResourceAsStream(POM_PROPERTIES)) {
            if (in != null) {
                Properties p = new Properties();
                p.load(in);
                version = p.getProperty("version", version);
            }
        } catch (IOException e) {
            version = "unknown";
        }
        String commit = null;
        try {
            CodeSource source = BuildInfo.class.getProtectionDomain().getCodeSource();
            if (source != null) {
                commit = headCommit(Path.of(source.getLocation().toURI())).orElse(null);
            }
        } catch (URISyntaxException | RuntimeException e) {
            commit = null;
        }
        return new BuildInfo(version, commit);
    }

    /**
     * @param start a file or folder inside a checkout (e.g. the jar's location)
     * @return the commit HEAD names in the nearest {@code .git} above it, if any
     */
    static Optional<String> headCommit(Path start) {
        for (Path dir = start.toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Path dotGit = dir.resolve(".git");
            try {
                if (Files.isDirectory(dotGit)) {
                    return resolveHead(dotGit, dotGit);
                }
                if (Files.isRegularFile(dotGit)) {
                    String line = Files.readString(dotGit).strip();
                    if (!line.startsWith("gitdir:")) {
                        return Optional.empty();
                    }
                    Path gitDir = dir.resolve(line.substring("gitdir:".length()).strip()).normalize();
                    Path common = gitDir;
                    Path commonFile = gitDir.resolve("commondir");
                    if (Files.isRegularFile(commonFile)) {
                        common = gitDir.resolve(Files.readString(commonFile).strip()).normalize();
                    }
                    return resolveHead(gitDir, common);
                }
            } catch (IOException e) {
                return Optional.empty();
            }
        }
        return Optional.empty();
    }

    private static Optional<String> resolveHead(Path gitDir, Path commonDir) throws IOException {
        Path headFile = gitDir.resolve("HEAD");
        if (!Files.isRegularFile(headFile)) {
            return Optional.empty();
        }
        String head = Files.readString(headFile).strip();
        if (!head.startsWith("ref:")) {
            return Optional.of(head);
        }
        String ref = head.substring(4).strip();
        for (Path base : new Path[] {gitDir, commonDir}) {
            Path refFile = base.resolve(ref);
            if (Files.isRegularFile(refFile)) {
                return Optional.of(Files.readString(refFile).strip());
            }
        }
        Path packed = commonDir.resolve("packed-refs");
        if (Files.isRegularFile(packed)) {
            for (String line : Files.readAllLines(packed)) {
                if (line.endsWith(" " + ref)) {
                    return Optional.of(line.substring(0, line.indexOf(' ')));
                }
            }
        }
        return Optional.empty();
    }
}
