package io.rtaware.player.protocol;

import com.code_intelligence.jazzer.junit.FuzzTest;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.Odometry;
import java.io.ByteArrayInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.util.List;

/**
 * Coverage-guided fuzzing of the Player wire protocol as it comes off a socket (issue 24): the
 * first byte says which side sent the stream (odd: a server, whose stream starts with the 32-byte
 * banner; even: a client), the rest is the stream. Every message the frame reader completes is
 * decoded by every body decoder of {@link PlayerCodec}, whichever its header names, so each
 * decoder sees every body shape. Malformed input may only be refused with a
 * {@link PlayerProtocolException} (or an {@link EOFException} where the stream ends between two
 * messages); any other throwable is a finding. Without {@code JAZZER_FUZZ=1} it replays the
 * corpus in {@code PlayerStreamFuzzTestInputs/}, seeded from the real Player 3.1/Stage captures.
 */
class PlayerStreamFuzzTest {

    /** A body limit far below the default, so the fuzzer spends its time in decoders, not in allocation. */
    private static final int MAX_BODY_BYTES = 64 * 1024;

    private final LaserData laser = new LaserData(1024);
    private final RangerData ranger = new RangerData(1024);
    private final Odometry odometry = new Odometry();

    /** Every body decoder, each kept to its own line so a finding's stack trace names it. */
    private final List<Decoder> decoders = List.of(
            r -> PlayerCodec.readAddress(r, "address"),
            PlayerCodec::readDataMode,
            PlayerCodec::readReplaceRule,
            PlayerCodec::readDeviceList,
            PlayerCodec::readDriverInfo,
            PlayerCodec::readDeviceRequest,
            PlayerCodec::readSynch,
            r -> {
                PlayerCodec.readPosition2dState(r, odometry);
                return odometry;
            },
            PlayerCodec::readVelocityCmd,
            PlayerCodec::readMotorPower,
            PlayerCodec::readGeometry,
            r -> {
                PlayerCodec.readLaserScan(r, laser);
                return laser;
            },
            PlayerCodec::readLaserConfig,
            r -> {
                PlayerCodec.readRangerData(r, ranger);
                return ranger;
            },
            PlayerCodec::readRangerConfig,
            PlayerCodec::readRangerGeometry,
            PlayerCodec::readSimulationPose2d);

    @FuzzTest(maxDuration = "20s")
    void decodingAStreamThrowsNothingButProtocolErrors(byte[] input) throws IOException {
        if (input.length == 0) {
            return;
        }
        ByteArrayInputStream in = new ByteArrayInputStream(input, 1, input.length - 1);
        try {
            if ((input[0] & 1) == 1) {
                byte[] banner = in.readNBytes(Banner.SIZE_BYTES);
                Banner.decode(banner, banner.length);
            }
            PlayerFrameReader frames = new PlayerFrameReader(0, MAX_BODY_BYTES);
            for (int i = 0; i < 16; i++) {
                PlayerHeader header = frames.read(in);
                byte[] message = frames.copyMessage();
                decodeEveryWay(message, PlayerHeader.SIZE_BYTES, header.size());
            }
        } catch (EOFException | PlayerProtocolException refused) {
            // the end of the stream, or the documented way to refuse malformed input
        }
    }

    private void decodeEveryWay(byte[] message, int offset, int length) {
        for (Decoder decoder : decoders) {
            try {
                decoder.decode(new XdrReader(message, offset, length));
            } catch (PlayerProtocolException refused) {
                // expected for most pairs of body and decoder
            }
        }
    }

    @FunctionalInterface
    private interface Decoder {
        Object decode(XdrReader r) throws PlayerProtocolException;
    }
}
