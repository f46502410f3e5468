package io.rtaware.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.XdrReader;
import java.io.ByteArrayInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Replays the requests of the captured libplayerc sessions (Player 3.1.1 + Stage 4.3, see
 * {@code captures/README.txt}) byte for byte against the simulator and checks that every reply
 * has the captured shape: type, interface, index, subtype and body size; and that data comes in
 * the captured kinds with the body sizes the 683-beam laser implies.
 */
class CaptureReplayTest {

    private record Frame(PlayerHeader header, byte[] bytes) {
    }

    private static List<Frame> frames(String resource, int skip) throws IOException {
        byte[] all;
        try (InputStream in = CaptureReplayTest.class.getResourceAsStream(resource)) {
            all = in.readAllBytes();
        }
        ByteArrayInputStream in = new ByteArrayInputStream(all, skip, all.length - skip);
        PlayerFrameReader reader = new PlayerFrameReader(skip, 1 << 22);
        List<Frame> out = new ArrayList<>();
        long offset = skip;
        while (true) {
            PlayerHeader h;
            try {
                h = reader.read(in);
            } catch (EOFException e) {
                return out;
            }
            int len = PlayerHeader.SIZE_BYTES + h.size();
            out.add(new Frame(h, Arrays.copyOfRange(all, (int) offset, (int) offset + len)));
            offset += len;
        }
    }

    private static String shape(PlayerHeader h) {
        return MessageType.name(h.type()) + " " + Interfaces.name(h.interf()) + ":" + h.index() + " subtype "
                + h.subtype() + " size " + h.size();
    }

    @ParameterizedTest
    @ValueSource(strings = {"pull", "push"})
    void repliesHaveTheCapturedShapes(String session) throws IOException {
        List<Frame> requests = frames("/captures/" + session + "/client-to-server.bin", 0);
        List<String> expectedReplies = new ArrayList<>();
        Set<String> expectedDataKinds = new TreeSet<>();
        for (Frame f : frames("/captures/" + session + "/server-to-client.bin", 32)) {
            int t = f.header().type();
            if (t == MessageType.RESP_ACK || t == MessageType.RESP_NACK) {
                expectedReplies.add(shape(f.header()));
            } else if (t == MessageType.DATA) {
                expectedDataKinds.add(Interfaces.name(f.header().interf()) + " " + f.header().subtype());
            }
        }
        assertTrue(expectedReplies.size() > 10);

        List<String> replies = new ArrayList<>();
        List<RawClient.Msg> seen = new ArrayList<>();
        try (PlayerSimServer server = PlayerSimServer.startManual(PlayerSimServerTest.world(), ServerConfig.defaults(0));
             RawClient c = new RawClient(server.port())) {
            for (Frame f : requests) {
                PlayerHeader h = f.header();
                boolean dataRequest = h.interf() == Interfaces.PLAYER && h.subtype() == Subtypes.PLAYER_REQ_DATA;
                if (dataRequest || h.type() == MessageType.CMD) {
                    for (int i = 0; i < 10; i++) {
                        server.step(10_000_000L); // the 100 ms Stage step between client reads
                    }
                }
                c.sendRaw(f.bytes());
                if (h.type() == MessageType.REQ) {
                    replies.add(shape(c.reply(seen).header()));
                }
            }
        }
        assertEquals(expectedReplies, replies);

        Set<String> dataKinds = new TreeSet<>();
        int beams = 683;
        for (RawClient.Msg m : seen) {
            PlayerHeader h = m.header();
            if (h.type() != MessageType.DATA) {
                continue;
            }
            dataKinds.add(Interfaces.name(h.interf()) + " " + h.subtype());
            int expectedSize = switch (h.interf()) {
                case Interfaces.POSITION2D -> 52;
                case Interfaces.LASER -> 16 + 4 + 4 + 4 * beams + 4 + 4 + XdrReader.padded(beams) + 4;
                case Interfaces.RANGER -> 4 + 4 + 8 * beams;
                default -> -1;
            };
            assertEquals(expectedSize, h.size(), shape(h));
        }
        assertEquals(expectedDataKinds, dataKinds);
    }
}
