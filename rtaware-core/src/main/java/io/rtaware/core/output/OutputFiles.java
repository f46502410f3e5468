package io.rtaware.core.output;

import java.awt.image.RenderedImage;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Iterator;
import java.util.Optional;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * Writes one output file through a stream, by what stands at its path (links followed):
 *
 * <ul>
 *   <li>nothing, or a regular file: the content goes to a temporary name in the same folder
 *       ({@link #partialName}) and is renamed over the file once complete, so the file is
 *       either whole or, after a failed write, as it was before (absent, or the older version);
 *       the temporary file is deleted. Through a link to a regular file, the file the link
 *       names is replaced and the link stays;</li>
 *   <li>a pipe (FIFO, e.g. {@code /dev/stdout} in a pipeline) or a character device (e.g.
 *       {@code /dev/null}): written in place, never deleted or replaced. Opening a pipe waits
 *       for its reader, as a shell's {@code >} does;</li>
 *   <li>a folder, a socket or a block device: refused with a {@link FileSystemException} whose
 *       reason says what stands there ({@link #refusal}), and left as it is.</li>
 * </ul>
 *
 * {@code ImageIO.write(image, format, File)} deletes whatever is at the path before it writes
 * (it replaced {@code /dev/full} with a PNG when run as root): images are written through
 * {@link #png} instead. Stateless and thread-safe (two writers of one path at once race on
 * its temporary name).
 */
public final class OutputFiles {

    /** File type bits of {@code unix:mode} (POSIX {@code S_IFMT}) and the two types refused. */
    private static final int TYPE_MASK = 0170000;
    private static final int SOCKET = 0140000;
    private static final int BLOCK_DEVICE = 0060000;

    /** A file's content, written to the stream it is given (which the caller closes). */
    @FunctionalInterface
    public interface Content {
        /**
         * @param out where the content goes
         * @throws IOException if writing fails
         */
        void writeTo(OutputStream out) throws IOException;
    }

    private OutputFiles() {
    }

    /**
     * Writes a file as the class says, creating its folder if needed.
     *
     * @param file where the content goes
     * @param content what it is
     * @throws IOException if it cannot be written; a {@link FileSystemException} naming the file
     *     and what stands there when the path is refused
     */
    public static void write(Path file, Content content) throws IOException {
        Optional<String> refused = refusal(file);
        if (refused.isPresent()) {
            throw new FileSystemException(file.toString(), null, refused.get());
        }
        BasicFileAttributes what = attributes(file);
        if (what != null && what.isOther()) {
            writeInPlace(file, content);
            return;
        }
        if (what == null && Files.isSymbolicLink(file)) {
            writeInPlace(file, content); // a link to nothing yet: create what it names, keep the link
            return;
        }
        Path target = what != null && Files.isSymbolicLink(file) ? file.toRealPath() : file;
        Path folder = target.toAbsolutePath().getParent();
        if (folder != null) {
            Files.createDirectories(folder);
        }
        Path temporary = partialName(target);
        try {
            Files.deleteIfExists(temporary); // left by a write that was killed
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(temporary,
                    StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE))) {
                content.writeTo(out);
            }
            Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /**
     * @param file an output path
     * @return why no file can be written there ({@code "a folder, not a file"}, {@code "a socket,
     *     not a file"}, {@code "a block device, not a file"}), or empty when one can (nothing is
     *     there, or a regular file, a pipe or a character device)
     * @throws IOException if what stands there cannot be read
     */
    public static Optional<String> refusal(Path file) throws IOException {
        BasicFileAttributes what = attributes(file);
        if (what == null) {
            return Optional.empty();
        }
        if (what.isDirectory()) {
            return Optional.of("a folder, not a file");
        }
        if (!what.isOther()) {
            return Optional.empty();
        }
        int type;
        try {
            type = (Integer) Files.getAttribute(file, "unix:mode") & TYPE_MASK;
        } catch (UnsupportedOperationException | IllegalArgumentException notUnix) {
            return Optional.empty(); // no file types to tell apart: written in place
        }
        return switch (type) {
            case SOCKET -> Optional.of("a socket, not a file");
            case BLOCK_DEVICE -> Optional.of("a block device, not a file");
            default -> Optional.empty();
        };
    }

    /**
     * @param file a file
     * @return the temporary name {@link #write} writes it under: {@code .NAME.partial.EXT} in
     *     its folder (the extension kept last, for tools that look at it)
     */
    public static Path partialName(Path file) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String partial = dot > 0 ? "." + name.substring(0, dot) + ".partial" + name.substring(dot)
                : "." + name + ".partial";
        return file.resolveSibling(partial);
    }

    /**
     * @param image an image
     * @return its content as PNG
     */
    public static Content png(RenderedImage image) {
        return out -> {
            Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
            if (!writers.hasNext()) {
                throw new IOException("this JVM has no PNG writer");
            }
            ImageWriter writer = writers.next();
            // Encoded in memory, then written: a failed write then says why (the PNG writer's own
            // says "I/O error writing PNG file!" for a full disk), and no ImageIO file cache is
            // used (its clean-up registers a shutdown hook, which fails for an image written while
            // the JVM shuts down, as a run's report after Ctrl-C is).
            ByteArrayOutputStream encoded = new ByteArrayOutputStream();
            try (ImageOutputStream stream = new MemoryCacheImageOutputStream(encoded)) {
                writer.setOutput(stream);
                writer.write(image);
            } finally {
                writer.dispose();
            }
            encoded.writeTo(out);
        };
    }

    /**
     * @param text a text
     * @return its content in UTF-8
     */
    public static Content text(CharSequence text) {
        return out -> out.write(text.toString().getBytes(StandardCharsets.UTF_8));
    }

    /** @return what stands at the path (links followed), or null when nothing does */
    private static BasicFileAttributes attributes(Path file) throws IOException {
        try {
            return Files.readAttributes(file, BasicFileAttributes.class);
        } catch (NoSuchFileException absent) {
            return null;
        }
    }

    private static void writeInPlace(Path file, Content content) throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(file, StandardOpenOption.CREATE,
                StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING))) {
            content.writeTo(out);
        }
    }

    /**
     * @param e an I/O failure
     * @return its one-line reason: the operating system's reason for a file system error (the
     *     path is named by the caller), the message otherwise
     */
    public static String reason(Exception e) {
        if (e instanceof FileSystemException fse) {
            if (fse.getReason() != null && !fse.getReason().isBlank()) {
                return fse.getReason();
            }
            return switch (e.getClass().getSimpleName()) {
                case "AccessDeniedException" -> "permission denied";
                case "NoSuchFileException" -> "no such file or folder";
                case "FileAlreadyExistsException" -> "a file is in the way";
                case "NotDirectoryException" -> "not a folder";
                default -> e.getClass().getSimpleName();
            };
        }
        String message = e.getMessage();
        return message == null || message.isBlank() ? e.getClass().getSimpleName()
                : message.lines().findFirst().orElse(message);
    }
}
