package io.rtaware.rt;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The PM QoS request, against a plain file standing in for /dev/cpu_dma_latency. */
class CpuLatencyRequestTest {

    @TempDir
    Path dir;

    @Test
    void writesTheLatencyAsOneLittleEndian32BitValueAndHoldsItUntilClosed() throws IOException {
        Path device = dir.resolve("cpu_dma_latency");
        Files.createFile(device);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Optional<CpuLatencyRequest> request = CpuLatencyRequest.hold(device, 0x0102_0304,
                new PrintStream(err, true, StandardCharsets.UTF_8));
        assertTrue(request.isPresent());
        assertArrayEquals(new byte[] {4, 3, 2, 1}, Files.readAllBytes(device));
        assertEquals(0x0102_0304, request.get().latencyUs());
        request.get().close();
        request.get().close();
        assertEquals("", err.toString(StandardCharsets.UTF_8), "nothing to say when the request is held");
    }

    @Test
    void zeroIsFourZeroBytes() throws IOException {
        Path device = dir.resolve("cpu_dma_latency");
        try (CpuLatencyRequest request = CpuLatencyRequest.hold(device, 0, System.err).orElseThrow()) {
            assertArrayEquals(new byte[4], Files.readAllBytes(device));
        }
    }

    @Test
    void aDeviceThatCannotBeOpenedGivesOneLineAndTheRunGoesOn() {
        Path missing = dir.resolve("no-such-dir").resolve("cpu_dma_latency");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Optional<CpuLatencyRequest> request = CpuLatencyRequest.hold(missing, 0,
                new PrintStream(err, true, StandardCharsets.UTF_8));
        assertTrue(request.isEmpty());
        String said = err.toString(StandardCharsets.UTF_8);
        assertEquals(1, said.lines().count(), said);
        assertTrue(said.contains(missing.toString()) && said.contains("deep idle"), said);
    }

    @Test
    void aNegativeLatencyIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> CpuLatencyRequest.hold(dir.resolve("x"), -1, System.err));
    }
}
