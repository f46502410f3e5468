package io.rtaware.core.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 38: an output file is written whole or not at all, and never replaces what is not a regular file. */
class OutputFilesTest {

    @TempDir
    Path dir;

    /** A content cut short by a full disk after some bytes, as the write of a large map is. */
    private static final OutputFiles.Content CUT_SHORT = out -> {
        out.write("P5\n8 6\n255\n".getBytes(StandardCharsets.US_ASCII));
        throw new IOException("No space left on device");
    };

    private List<String> names() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aCompleteWriteAppearsUnderItsNameOnlyOnceComplete() throws IOException {
        Path file = dir.resolve("sub/report.json");
        OutputFiles.write(file, out -> {
            assertFalse(Files.exists(file), "the file appears only once complete");
            assertTrue(Files.exists(dir.resolve("sub/.report.partial.json")), "written under a temporary name");
            out.write("{}".getBytes(StandardCharsets.UTF_8));
        });
        assertEquals("{}", Files.readString(file));
        try (Stream<Path> files = Files.list(file.getParent())) {
            assertEquals(1, files.count(), "no temporary file left");
        }
    }

    @Test
    void aWriteCutShortLeavesNoFileWhereThereWasNone() throws IOException {
        IOException e = assertThrows(IOException.class, () -> OutputFiles.write(dir.resolve("map.pgm"), CUT_SHORT));
        assertEquals("No space left on device", e.getMessage());
        assertEquals(List.of(), names(), "neither a truncated map.pgm nor a temporary file");
    }

    @Test
    void aWriteCutShortLeavesTheOlderFileAsItWas() throws IOException {
        Path file = Files.writeString(dir.resolve("map.pgm"), "the older map");
        assertThrows(IOException.class, () -> OutputFiles.write(file, CUT_SHORT));
        assertEquals("the older map", Files.readString(file));
        assertEquals(List.of("map.pgm"), names());
    }

    @Test
    void aLinkToAFileKeepsBeingALinkAndItsFileIsReplacedWhole() throws IOException {
        Path real = Files.writeString(dir.resolve("real.csv"), "old");
        Path link = Files.createSymbolicLink(dir.resolve("trajectory.csv"), real);
        OutputFiles.write(link, OutputFiles.text("new"));
        assertTrue(Files.isSymbolicLink(link), "the link stays a link");
        assertEquals("new", Files.readString(real));
        assertThrows(IOException.class, () -> OutputFiles.write(link, CUT_SHORT));
        assertEquals("new", Files.readString(real), "a failed write through the link keeps the file whole");
    }

    @Test
    void aCharacterDeviceIsWrittenInPlace() throws IOException {
        Path devNull = Path.of("/dev/null");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(devNull), "/dev/null");
        OutputFiles.write(devNull, OutputFiles.text("gone"));
        assertTrue(Files.readAttributes(devNull, java.nio.file.attribute.BasicFileAttributes.class).isOther(),
                "still a device");
    }

    @Test
    void aFolderAndASocketAreRefusedAndLeftAsTheyAre() throws IOException {
        Path folder = Files.createDirectories(dir.resolve("plot.png"));
        FileSystemException e = assertThrows(FileSystemException.class,
                () -> OutputFiles.write(folder, OutputFiles.text("x")));
        assertEquals("a folder, not a file", e.getReason());
        assertTrue(Files.isDirectory(folder));
        Path socket = dir.resolve("plot.sock");
        try (ServerSocketChannel server = ServerSocketChannel.open(StandardProtocolFamily.UNIX)) {
            server.bind(UnixDomainSocketAddress.of(socket));
            assertEquals(Optional.of("a socket, not a file"), OutputFiles.refusal(socket));
            e = assertThrows(FileSystemException.class, () -> OutputFiles.write(socket, OutputFiles.text("x")));
            assertEquals(socket.toString(), e.getFile());
            assertTrue(Files.readAttributes(socket, java.nio.file.attribute.BasicFileAttributes.class).isOther(),
                    "still a socket");
        }
        assertEquals(Optional.empty(), OutputFiles.refusal(dir.resolve("absent.png")));
    }
}
