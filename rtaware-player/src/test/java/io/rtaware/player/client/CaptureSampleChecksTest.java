package io.rtaware.player.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.player.Captures;
import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.RangerConfig;
import io.rtaware.player.protocol.Subtypes;
import java.io.ByteArrayInputStream;
import java.io.EOFException;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The plausibility rules against real traffic: every data message of both recorded Player
 * sessions goes through the client's own dispatch, and none may be rejected.
 */
class CaptureSampleChecksTest {

    @ParameterizedTest
    @ValueSource(strings = {"pull", "push-with-ranger"})
    void realTrafficHasNoRejectedSample(String session) throws Exception {
        byte[] stream = Captures.bytes(session, "server-to-client.bin");
        PlayerCounters counters = new PlayerCounters();
        SubscribedData data = new SubscribedData(counters, 4096);
        data.subscribed(Interfaces.POSITION2D, 0);
        data.subscribed(Interfaces.LASER, 0);
        data.subscribed(Interfaces.RANGER, 0);
        // The sessions hold no ranger GET_CONFIG reply; Player's rangertolaser laser:0 reports
        // the same ranger's field of view and maximum range, so its first scan configures it.
        LaserData firstScan = new LaserData(4096);
        for (Frame f = new Frame(stream); f.next(); ) {
            if (f.header.type() == MessageType.DATA && f.header.interf() == Interfaces.LASER
                    && f.header.subtype() == Subtypes.LASER_DATA_SCAN) {
                PlayerCodec.readLaserScan(f.frames.body(), firstScan);
                break;
            }
        }
        data.rangerConfigured(0, new RangerConfig(firstScan.minAngleRad, firstScan.maxAngleRad,
                firstScan.resolutionRad, 0, firstScan.maxRangeM, 0, 10));
        for (Frame f = new Frame(stream); f.next(); ) {
            data.dispatch(f.header, f.frames.body());
        }
        PlayerStats stats = counters.snapshot();
        assertEquals(0, stats.protocolErrors(), data.lastProtocolError());
        assertEquals(0, stats.rejectedOdometry(), counters.odometryChecks().lastRejection());
        assertEquals(0, stats.rejectedScans(), counters.laserChecks().lastRejection() + " / "
                + counters.rangerChecks().lastRejection());
        assertEquals(60, data.odometryUpdates());
        assertTrue(data.laserUpdates() >= 60, "laser scans kept: " + data.laserUpdates());
        if (session.equals("push-with-ranger")) {
            assertEquals(60, data.rangerUpdates());
        }
    }

    /** Walks the messages of a server-to-client stream. */
    private static final class Frame {
        final PlayerFrameReader frames = new PlayerFrameReader(Banner.SIZE_BYTES,
                PlayerFrameReader.DEFAULT_MAX_BODY_BYTES);
        final ByteArrayInputStream in;
        PlayerHeader header;

        Frame(byte[] stream) {
            in = new ByteArrayInputStream(stream, Banner.SIZE_BYTES, stream.length - Banner.SIZE_BYTES);
        }

        boolean next() throws Exception {
            try {
                header = frames.read(in);
                return true;
            } catch (EOFException end) {
                return false;
            }
        }
    }
}
