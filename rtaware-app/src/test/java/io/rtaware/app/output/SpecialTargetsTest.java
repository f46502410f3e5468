package io.rtaware.app.output;

import io.rtaware.core.output.OutputWrites;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 38: an image named on the command line never replaces what stands at its path.
 * {@code ImageIO.write(image, "png", File)} deleted it first: {@code world --png} and
 * {@code bench --sweep-tasks --plot} turned a pipe, a socket (or, as root, {@code /dev/full})
 * into a regular file. A pipe is written in place, a socket is refused in one line.
 */
class SpecialTargetsTest {

    private static final int TYPE_MASK = 0170000;
    private static final int FIFO = 0010000;
    private static final int SOCKET = 0140000;
    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

    /** The sweep's fastest run: one task, both pooled executors, one 2 ms segment after the warm-up round. */
    private static final String[] SWEEP = {"bench", "--sweep-tasks", "1", "--period", "1ms", "--work", "0",
        "--segment", "2ms", "--duration", "2ms", "--executor", "pooled", "--plot"};

    @TempDir
    Path dir;

    private final ExecutorService readers = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "fifo-reader");
        t.setDaemon(true); // a reader left waiting on a pipe that was deleted must not keep the JVM
        return t;
    });

    @AfterEach
    void stopReaders() {
        readers.shutdownNow();
    }

    private static final String[] WORLD = {"world", "--scenario", "paper-room", "--png"};

    @Test
    void worldWritesIntoAPipeInPlace() throws Exception {
        writesIntoAPipeInPlace("world.png", "world written to ", WORLD);
    }

    @Test
    void worldRefusesASocketInOneLineAndLeavesIt() throws Exception {
        refusesASocketInOneLineAndLeavesIt("world.sock", "--png", WORLD);
    }

    @Test
    void worldOnAFullDeviceSaysWhyInOneLineAndLeavesTheDevice() throws Exception {
        Path full = Path.of("/dev/full");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(full), "/dev/full (a device whose writes fail with ENOSPC)");
        Path link = Files.createSymbolicLink(dir.resolve("world.png"), full);
        CliRun r = CliRun.of(with(WORLD, link.toString()));
        assertEquals(OutputWrites.EXIT_WRITE_FAILED, r.status(), r.toString());
        assertEquals("rtaware: could not write " + link + ": No space left on device", r.err().strip());
        assertTrue(Files.isSymbolicLink(link), "the link stays a link");
        assertEquals(0020000, type(full), "/dev/full is still a character device");
    }

    @Test
    void benchSweepWritesItsPlotIntoAPipeInPlace() throws Exception {
        writesIntoAPipeInPlace("sweep.png", "plot written to ", SWEEP);
    }

    @Test
    void benchSweepRefusesASocketBeforeItRuns() throws Exception {
        assertFalse(refusesASocketInOneLineAndLeavesIt("sweep.sock", "--plot", SWEEP).out().contains("sweep:"),
                "nothing ran");
    }

    /** The command, given a pipe with a reader waiting, writes the PNG into it and leaves it a pipe. */
    private void writesIntoAPipeInPlace(String name, String written, String... command) throws Exception {
        Path fifo = fifo(name);
        CompletableFuture<byte[]> read = CompletableFuture.supplyAsync(() -> readAll(fifo), readers);
        CliRun r = CliRun.of(with(command, fifo.toString()));
        assertEquals(FIFO, type(fifo), "the pipe is still a pipe; " + r);
        releaseReader(fifo);
        assertEquals(0, r.status(), r.toString());
        assertTrue(r.out().contains(written + fifo), r.out());
        assertArrayEquals(PNG_SIGNATURE, Arrays.copyOf(read.get(), PNG_SIGNATURE.length), "the reader got the PNG");
    }

    /** The command, given a listening Unix socket, refuses it in one line and leaves it a socket. */
    private CliRun refusesASocketInOneLineAndLeavesIt(String name, String option, String... command) throws Exception {
        Path socket = dir.resolve(name);
        try (ServerSocketChannel server = ServerSocketChannel.open(StandardProtocolFamily.UNIX)) {
            server.bind(UnixDomainSocketAddress.of(socket));
            CliRun r = CliRun.of(with(command, socket.toString()));
            r.assertOneLineUserError(option + ": " + socket + " is a socket, not a file");
            assertEquals(SOCKET, type(socket), "the socket is still a socket");
            return r;
        }
    }

    private Path fifo(String name) throws IOException, InterruptedException {
        Path fifo = dir.resolve(name);
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).inheritIO().start();
        assertEquals(0, mkfifo.waitFor(), "mkfifo " + fifo);
        assertEquals(FIFO, type(fifo));
        return fifo;
    }

    private static byte[] readAll(Path fifo) {
        try {
            return Files.readAllBytes(fifo); // opening waits for a writer; EOF when it closes
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /**
     * Opens and closes the pipe for reading and writing (which never waits on Linux), so a reader
     * still waiting for a writer (the command never opened the pipe) sees the end at once.
     */
    private static void releaseReader(Path fifo) throws IOException {
        new RandomAccessFile(fifo.toFile(), "rw").close();
    }

    private static int type(Path file) throws IOException {
        return (Integer) Files.getAttribute(file, "unix:mode", LinkOption.NOFOLLOW_LINKS) & TYPE_MASK;
    }

    private static String[] with(String[] args, String last) {
        String[] all = Arrays.copyOf(args, args.length + 1);
        all[args.length] = last;
        return all;
    }
}
