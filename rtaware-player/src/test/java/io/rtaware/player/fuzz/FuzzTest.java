package io.rtaware.player.fuzz;

import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.player.Captures;
import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.RangerData;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.Odometry;
import java.io.ByteArrayInputStream;
import java.io.EOFException;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Random and mutated streams through the frame reader and every body decoder: the only
 * exception allowed is {@link PlayerProtocolException} (and end of stream between messages).
 */
@Timeout(20)
class FuzzTest {

    private static final int MAX_BODY = 64 * 1024;
    private final LaserData laser = new LaserData(1024);
    private final RangerData ranger = new RangerData(1024);
    private final Odometry odo = new Odometry();

    /** Decodes a whole stream; returns the messages decoded. */
    private int decodeStream(byte[] stream, int start) throws Exception {
        PlayerFrameReader frames = new PlayerFrameReader(start, MAX_BODY);
        ByteArrayInputStream in = new ByteArrayInputStream(stream, start, stream.length - start);
        int n = 0;
        while (true) {
            PlayerHeader h;
            try {
                h = frames.read(in);
            } catch (EOFException end) {
                return n;
            } catch (PlayerProtocolException broken) {
                assertTrue(broken.getMessage().contains("field"), broken.getMessage());
                return n;
            }
            n++;
            decodeEveryWay(frames.body());
        }
    }

    /** Runs every body decoder on the body: each must decode or throw PlayerProtocolException. */
    private void decodeEveryWay(XdrReader body) throws Exception {
        int size = body.remaining();
        for (int kind = 0; kind < 16; kind++) {
            body = body.reset(body.array(), body.start(), size, body.baseOffset());
            try {
                switch (kind) {
                    case 0 -> PlayerCodec.readDataMode(body);
                    case 1 -> PlayerCodec.readDeviceList(body);
                    case 2 -> PlayerCodec.readDriverInfo(body);
                    case 3 -> PlayerCodec.readDeviceRequest(body);
                    case 4 -> PlayerCodec.readReplaceRule(body);
                    case 5 -> PlayerCodec.readSynch(body);
                    case 6 -> PlayerCodec.readPosition2dState(body, odo);
                    case 7 -> PlayerCodec.readVelocityCmd(body);
                    case 8 -> PlayerCodec.readGeometry(body);
                    case 9 -> PlayerCodec.readLaserScan(body, laser);
                    case 10 -> PlayerCodec.readLaserConfig(body);
                    case 11 -> PlayerCodec.readRangerData(body, ranger);
                    case 12 -> PlayerCodec.readRangerConfig(body);
                    case 13 -> PlayerCodec.readRangerGeometry(body);
                    case 14 -> PlayerCodec.readSimulationPose2d(body);
                    default -> PlayerCodec.readMotorPower(body);
                }
            } catch (PlayerProtocolException expected) {
                assertTrue(expected.offset() >= 0 && expected.field() != null);
            }
        }
    }

    @Test
    void mutatedCapturesGiveOnlyProtocolErrors() throws Exception {
        Random random = new Random(20261122L);
        byte[][] streams = {Captures.bytes("pull", "server-to-client.bin"),
                Captures.bytes("pull", "client-to-server.bin"),
                Captures.bytes("push-with-ranger", "server-to-client.bin"),
                Captures.bytes("push-with-ranger", "client-to-server.bin")};
        int decoded = 0;
        for (int round = 0; round < 400; round++) {
            byte[] original = streams[round % streams.length];
            int start = round % 2 == 0 ? Banner.SIZE_BYTES : 0;
            int cut = Math.min(original.length, start + 4000 + random.nextInt(12000));
            byte[] s = java.util.Arrays.copyOf(original, cut);
            int flips = 1 + random.nextInt(8);
            for (int i = 0; i < flips; i++) {
                int at = start + random.nextInt(s.length - start);
                switch (random.nextInt(3)) {
                    case 0 -> s[at] ^= (byte) (1 << random.nextInt(8));
                    case 1 -> s[at] = (byte) random.nextInt(256);
                    default -> s[at] = (byte) 0xff;
                }
            }
            decoded += decodeStream(s, start);
        }
        assertTrue(decoded > 1000, "mutations should leave most messages decodable: " + decoded);
    }

    @Test
    void randomBytesGiveOnlyProtocolErrors() throws Exception {
        Random random = new Random(7);
        for (int round = 0; round < 2000; round++) {
            byte[] s = new byte[random.nextInt(400)];
            random.nextBytes(s);
            if (s.length >= 40 && random.nextBoolean()) {
                // plausible header: small size, known interface
                s[36] = 0;
                s[37] = 0;
                s[38] = 0;
                s[39] = (byte) random.nextInt(s.length - 40 + 1);
                s[11] = (byte) Interfaces.LASER;
                s[19] = (byte) MessageType.DATA;
            }
            decodeStream(s, 0);
            try {
                Banner.decode(s, s.length);
            } catch (PlayerProtocolException expected) {
                assertTrue(expected.getMessage().contains("banner"));
            }
        }
    }
}
