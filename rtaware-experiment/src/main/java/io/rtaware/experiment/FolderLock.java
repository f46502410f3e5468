package io.rtaware.experiment;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.function.LongPredicate;

/**
 * Keeps a second {@code rtaware experiment} out of a folder while one is writing it (two writers
 * used to append the same runs twice to {@code results.csv}). The lock is the file
 * {@value #FILE_NAME} holding the owner's process id, plus an operating-system lock on that
 * file that the kernel releases when the owner dies, however it dies:
 * <ul>
 *   <li>the OS lock is held by another process (or this one): refused, naming the pid;</li>
 *   <li>the file names a process that is still alive: refused (its owner may not hold an OS
 *       lock, e.g. it runs on another file system view); the message names the file to delete if
 *       that process is not an experiment;</li>
 *   <li>the file names a process that is dead, or is unreadable: taken over.</li>
 * </ul>
 * {@link #close()} releases the lock and deletes the file. Not thread-safe.
 */
public final class FolderLock implements AutoCloseable {

    /** The lock file's name inside the experiment folder. */
    public static final String FILE_NAME = "experiment.lock";

    private final Path file;
    private final FileChannel channel;
    private final FileLock lock;

    private FolderLock(Path file, FileChannel channel, FileLock lock) {
        this.file = file;
        this.channel = channel;
        this.lock = lock;
    }

    /**
     * @param dir the experiment folder (it exists)
     * @return the lock, held until {@link #close()}
     * @throws ExperimentInputException if another live process owns the folder
     * @throws IOException if the lock file cannot be written
     */
    public static FolderLock acquire(Path dir) throws IOException {
        return acquire(dir, ProcessHandle.current().pid(),
                pid -> ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false));
    }

    static FolderLock acquire(Path dir, long ownPid, LongPredicate alive) throws IOException {
        Path file = dir.resolve(FILE_NAME);
        OptionalLong recorded = readPid(file);
        FileChannel channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.READ,
                StandardOpenOption.WRITE);
        FileLock lock;
        try {
            lock = channel.tryLock();
        } catch (OverlappingFileLockException sameProcess) {
            lock = null;
        } catch (IOException e) {
            channel.close();
            throw e;
        }
        if (lock == null) {
            channel.close();
            throw new ExperimentInputException(dir + " is in use by another rtaware experiment"
                    + (recorded.isPresent() ? " (pid " + recorded.getAsLong() + ")" : "")
                    + "; wait for it to end, or use another --out");
        }
        if (recorded.isPresent() && recorded.getAsLong() != ownPid && alive.test(recorded.getAsLong())) {
            lock.release();
            channel.close();
            throw new ExperimentInputException(dir + " is in use by another rtaware experiment (pid "
                    + recorded.getAsLong() + ", " + file + "); wait for it to end, or delete that file if pid "
                    + recorded.getAsLong() + " is not an experiment");
        }
        try {
            channel.truncate(0);
            channel.write(ByteBuffer.wrap((ownPid + "\n").getBytes(StandardCharsets.US_ASCII)), 0);
            channel.force(true);
        } catch (IOException e) {
            lock.release();
            channel.close();
            throw e;
        }
        return new FolderLock(file, channel, lock);
    }

    /**
     * Whether another live process holds the folder, without taking it: its lock file is locked,
     * or names a live process other than this one.
     *
     * @param dir an experiment folder
     * @return the holder's pid (or -1 when its lock file names none), if the folder is in use
     * @throws IOException if the lock file exists but cannot be opened
     */
    public static OptionalLong inUse(Path dir) throws IOException {
        Path file = dir.resolve(FILE_NAME);
        if (!Files.exists(file)) {
            return OptionalLong.empty();
        }
        OptionalLong recorded = readPid(file);
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ, StandardOpenOption.WRITE)) {
            FileLock lock;
            try {
                lock = channel.tryLock();
            } catch (OverlappingFileLockException sameProcess) {
                lock = null;
            }
            if (lock == null) {
                return OptionalLong.of(recorded.orElse(-1));
            }
            lock.release();
        }
        long own = ProcessHandle.current().pid();
        if (recorded.isPresent() && recorded.getAsLong() != own
                && ProcessHandle.of(recorded.getAsLong()).map(ProcessHandle::isAlive).orElse(false)) {
            return recorded;
        }
        return OptionalLong.empty();
    }

    /**
     * @param dir an experiment folder
     * @return the pid in its lock file, if there is a readable one
     */
    public static Optional<Long> owner(Path dir) {
        OptionalLong pid = readPid(dir.resolve(FILE_NAME));
        return pid.isPresent() ? Optional.of(pid.getAsLong()) : Optional.empty();
    }

    private static OptionalLong readPid(Path file) {
        try {
            String text = Files.readString(file, StandardCharsets.US_ASCII).strip();
            return text.isEmpty() ? OptionalLong.empty() : OptionalLong.of(Long.parseLong(text));
        } catch (IOException | NumberFormatException e) {
            return OptionalLong.empty();
        }
    }

    /** @return the lock file */
    public Path file() {
        return file;
    }

    @Override
    public void close() throws IOException {
        try {
            Files.deleteIfExists(file);
        } finally {
            lock.release();
            channel.close();
        }
    }
}
