package io.rtaware.bench;

import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.LaserScan;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Decoding throughput of Player laser scans: one captured {@code DATA laser SCAN} message
 * from Stage (241 beams with intensities, 1284 bytes with its header). Scores are scans per
 * second; multiply by 1284 for bytes per second. Per-thread state; not shared.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
public class PlayerDecodeBench {

    /** Bytes of the captured message, header included. */
    public static final int MESSAGE_BYTES = 1284;

    private byte[] message;
    private final XdrReader reader = new XdrReader();
    private final LaserData laser = new LaserData(4096);
    private final LaserScan scan = new LaserScan();

    /** Loads the captured scan. */
    @Setup
    public void load() {
        try (InputStream in = PlayerDecodeBench.class.getResourceAsStream("/player/laser-scan.bin")) {
            message = in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        if (message.length != MESSAGE_BYTES) {
            throw new IllegalStateException("laser-scan.bin has " + message.length + " bytes");
        }
    }

    /**
     * Header and body decoded from the array into reusable buffers, then copied into the
     * data-store scan.
     *
     * @return the scan, so the work is not eliminated
     * @throws PlayerProtocolException never, for the captured message
     */
    @Benchmark
    public LaserScan decodeScan() throws PlayerProtocolException {
        reader.reset(message, 0, message.length, 0);
        PlayerHeader h = PlayerHeader.decode(reader);
        PlayerCodec.readLaserScan(reader, laser);
        laser.toLaserScan(scan, h.timestampS());
        return scan;
    }

    /**
     * The same message cut from a stream by the frame reader (as the client does), then
     * decoded.
     *
     * @return the scan
     * @throws IOException never, for the captured message
     */
    @Benchmark
    public LaserScan frameAndDecodeScan() throws IOException {
        PlayerFrameReader frames = new PlayerFrameReader(0, PlayerFrameReader.DEFAULT_MAX_BODY_BYTES);
        PlayerHeader h = frames.read(new ByteArrayInputStream(message));
        PlayerCodec.readLaserScan(frames.body(), laser);
        laser.toLaserScan(scan, h.timestampS());
        return scan;
    }
}
