package io.rtaware.docs;

import java.io.File;
import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * Compiles code the way a library user's build does: with {@code javac} (the JDK's
 * {@code javax.tools}) against the library on the class path, and nothing of these tests.
 */
final class UserCompiler {

    private UserCompiler() {
    }

    /**
     * The class path a user of the library has: this test's class path (the modules this module
     * depends on, and theirs) without this module's own test classes.
     *
     * @return the class path, entries separated by {@link File#pathSeparator}
     */
    static String libraryClassPath() {
        Path tests;
        try {
            tests = Path.of(UserCompiler.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
        return Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator))
                .filter(entry -> !entry.isEmpty() && !Path.of(entry).toAbsolutePath().equals(tests.toAbsolutePath()))
                .collect(Collectors.joining(File.pathSeparator));
    }

    /**
     * An error or warning of the compiler.
     *
     * @param file the source file's name, or empty for one about no file
     * @param line its line in that file (from 1), or -1
     * @param message {@code error: ...} or {@code warning: ...}
     */
    record Problem(String file, long line, String message) {
        @Override
        public String toString() {
            return file.isEmpty() ? message : file + ":" + line + ": " + message;
        }
    }

    /**
     * Writes each source under {@code root/src} and compiles them all together into
     * {@code root/classes}, every lint warning on.
     *
     * @param sources file path (e.g. {@code com/example/Main.java}) to its text
     * @param root a folder of the test's own
     * @return every error and warning; empty when the code compiled cleanly
     * @throws IOException if a file cannot be written
     */
    static List<Problem> compile(Map<String, String> sources, Path root) throws IOException {
        List<File> files = new ArrayList<>();
        for (Map.Entry<String, String> source : sources.entrySet()) {
            Path file = root.resolve("src").resolve(source.getKey());
            Files.createDirectories(file.getParent());
            Files.writeString(file, source.getValue(), StandardCharsets.UTF_8);
            files.add(file.toFile());
        }
        Path classes = Files.createDirectories(root.resolve("classes"));
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager fileManager = javac.getStandardFileManager(diagnostics, Locale.ROOT,
                StandardCharsets.UTF_8)) {
            javac.getTask(null, fileManager, diagnostics,
                    List.of("-d", classes.toString(), "-classpath", libraryClassPath(), "-proc:none", "-Xlint:all"),
                    null, fileManager.getJavaFileObjectsFromFiles(files)).call();
        }
        List<Problem> problems = new ArrayList<>();
        for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
            if (d.getKind() != Diagnostic.Kind.NOTE) {
                problems.add(new Problem(d.getSource() == null ? "" : Path.of(d.getSource().toUri()).getFileName().toString(),
                        d.getLineNumber(), d.getKind().toString().toLowerCase(Locale.ROOT) + ": " + d.getMessage(Locale.ROOT)));
            }
        }
        return problems;
    }
}
