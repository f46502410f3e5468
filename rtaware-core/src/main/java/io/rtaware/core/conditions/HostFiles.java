package io.rtaware.core.conditions;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * The operating system's files ({@code /proc}, {@code /sys}) under a root: {@code /} for this
 * machine, a folder of fixture files in tests. A file that is missing or unreadable is empty,
 * never an error: conditions are read on any OS and say "unknown" for what it does not expose.
 * Thread-safe.
 */
public final class HostFiles {

    private final Path root;

    /** @param root the folder that stands for {@code /} */
    public HostFiles(Path root) {
        this.root = Objects.requireNonNull(root, "root");
    }

    /** @return this machine's files */
    public static HostFiles system() {
        return new HostFiles(Path.of("/"));
    }

    /**
     * @param absolutePath a path as on the machine, e.g. {@code /proc/stat}
     * @return the file's text, or empty if it is missing or unreadable
     */
    public Optional<String> read(String absolutePath) {
        Path file = resolve(absolutePath);
        try {
            return Files.isReadable(file) ? Optional.of(Files.readString(file)) : Optional.empty();
        } catch (IOException | RuntimeException e) {
            return Optional.empty();
        }
    }

    /**
     * @param absolutePath a path as on the machine
     * @return its first line, stripped, or empty if the file is missing, unreadable or empty
     */
    public Optional<String> firstLine(String absolutePath) {
        return read(absolutePath).map(t -> t.lines().findFirst().orElse("").strip()).filter(s -> !s.isEmpty());
    }

    /**
     * @param absolutePath a folder as on the machine, e.g. {@code /proc/self/task}
     * @return the names of its entries, or an empty list if it is missing
     */
    public List<String> list(String absolutePath) {
        Path dir = resolve(absolutePath);
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        List<String> names = new ArrayList<>();
        try (Stream<Path> entries = Files.list(dir)) {
            entries.forEach(p -> names.add(p.getFileName().toString()));
        } catch (IOException | RuntimeException e) {
            return List.of();
        }
        return names;
    }

    private Path resolve(String absolutePath) {
        String relative = absolutePath.startsWith("/") ? absolutePath.substring(1) : absolutePath;
        return root.resolve(relative);
    }
}
