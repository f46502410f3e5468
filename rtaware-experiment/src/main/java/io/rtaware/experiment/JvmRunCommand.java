package io.rtaware.experiment;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * Runs each trial in a fresh JVM, as each trial on the robot was a fresh program: the same
 * {@code java} and class path as the current process, the JVM options it was started with
 * (those of {@code RTAWARE_JAVA_OPTS}, minus debugger and agent options that cannot be shared),
 * then {@code MAIN run ARGS}.
 *
 * @param javaBin the java executable
 * @param jvmOptions options placed before the main class
 * @param classPath the class path
 * @param mainClass a class whose {@code main} understands {@code run ARGS}
 */
public record JvmRunCommand(String javaBin, List<String> jvmOptions, String classPath, String mainClass)
        implements RunCommand {

    /** The rtaware command line's main class. */
    public static final String RTAWARE_MAIN = "io.rtaware.app.RtawareCli";

    private static final List<String> NOT_INHERITED = List.of("-agentlib", "-agentpath", "-javaagent", "-Xrunjdwp", "-Xdebug");

    /**
     * Validates and copies the fields.
     *
     * @param javaBin the java executable
     * @param jvmOptions options placed before the main class
     * @param classPath the class path
     * @param mainClass a class whose {@code main} understands {@code run ARGS}
     */
    public JvmRunCommand {
        Objects.requireNonNull(javaBin, "javaBin");
        jvmOptions = List.copyOf(jvmOptions);
        Objects.requireNonNull(classPath, "classPath");
        Objects.requireNonNull(mainClass, "mainClass");
    }

    /**
     * @param mainClass the main class to run in the child JVM
     * @return a command with this process's java, JVM options and class path
     */
    public static JvmRunCommand ofCurrentProcess(String mainClass) {
        String javaBin = ProcessHandle.current().info().command()
                .orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        List<String> options = ManagementFactory.getRuntimeMXBean().getInputArguments().stream()
                .filter(o -> NOT_INHERITED.stream().noneMatch(o::startsWith))
                .toList();
        List<String> classPath = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(java.io.File.pathSeparator)) {
            classPath.add(entry.isEmpty() ? entry : Path.of(entry).toAbsolutePath().toString());
        }
        return new JvmRunCommand(javaBin, options, String.join(java.io.File.pathSeparator, classPath), mainClass);
    }

    @Override
    public List<String> commandLine(List<String> runArguments) {
        List<String> cmd = new ArrayList<>();
        cmd.add(javaBin);
        cmd.addAll(jvmOptions);
        cmd.add("-cp");
        cmd.add(classPath);
        cmd.add(mainClass);
        cmd.add("run");
        cmd.addAll(runArguments);
        return cmd;
    }
}
