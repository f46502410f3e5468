package io.rtaware.buildtests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.ByteArrayOutputStream;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The archetype's Java templates (rtaware-archetype's {@code archetype-resources}) compile against
 * this build's rtaware-core, warnings as errors, and the generated project's test passes on it: a
 * change of the core's API that would break every project generated from the archetype fails
 * {@code verify} here. {@code .ci/run} goes further after {@code install}: it generates a project
 * from the installed archetype, builds and tests it with Maven and runs its main
 * ({@code scripts/archetype-check.sh}).
 */
class ArchetypeTemplateTest {

    private static final Path TEMPLATES = Fixture.ROOT.resolve("rtaware-archetype/src/main/resources/archetype-resources");
    private static final String PACKAGE = "com.example.robot";

    @TempDir
    Path dir;

    /** The templates of one source tree as the archetype writes them for {@link #PACKAGE}. */
    private List<Path> generate(String tree) throws Exception {
        List<Path> sources = new ArrayList<>();
        try (Stream<Path> files = Files.list(TEMPLATES.resolve(tree))) {
            for (Path template : files.filter(f -> f.toString().endsWith(".java")).sorted().toList()) {
                String text = Files.readString(template, StandardCharsets.UTF_8).replace("${package}", PACKAGE);
                assertFalse(text.contains("${"), template + " uses no Velocity reference but ${package}");
                Path source = dir.resolve("src").resolve(PACKAGE.replace('.', '/')).resolve(template.getFileName());
                Files.createDirectories(source.getParent());
                Files.writeString(source, text, StandardCharsets.UTF_8);
                sources.add(source);
            }
        }
        return sources;
    }

    @Test
    void theTemplatesCompileAgainstThisBuildsCoreAndTheirTestPasses() throws Throwable {
        List<String> args = new ArrayList<>(List.of("--release", "17", "-Xlint:all,-path", "-Werror", "-proc:none",
                "-d", dir.resolve("classes").toString(),
                // surefire runs the tests from a manifest-only jar; this property has the real class path
                "-classpath", System.getProperty("surefire.test.class.path", System.getProperty("java.class.path"))));
        generate("src/main/java").forEach(source -> args.add(source.toString()));
        generate("src/test/java").forEach(source -> args.add(source.toString()));
        ByteArrayOutputStream errors = new ByteArrayOutputStream();

        int status = ToolProvider.getSystemJavaCompiler().run(null, errors, errors, args.toArray(String[]::new));

        assertEquals(0, status, "the templates compile:\n" + errors.toString(StandardCharsets.UTF_8));
        try (URLClassLoader loader = new URLClassLoader(new URL[] {dir.resolve("classes").toUri().toURL()},
                getClass().getClassLoader())) {
            runTests(loader.loadClass(PACKAGE + ".SpeedGuardTest"));
        }
    }

    /** Runs each {@code @Test} method of a test class without lifecycle methods, each on a new instance. */
    private static void runTests(Class<?> testClass) throws Throwable {
        int ran = 0;
        for (Method method : testClass.getDeclaredMethods()) {
            if (method.isAnnotationPresent(Test.class)) {
                var constructor = testClass.getDeclaredConstructor();
                constructor.setAccessible(true);
                method.setAccessible(true);
                try {
                    method.invoke(constructor.newInstance());
                } catch (InvocationTargetException e) {
                    throw e.getCause();
                }
                ran++;
            }
        }
        assertEquals(2, ran, "the generated project's two tests ran");
    }
}
