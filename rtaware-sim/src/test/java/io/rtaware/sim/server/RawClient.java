package io.rtaware.sim.server;

import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/** A test client speaking the Player protocol with the rtaware-player codec. Not thread-safe. */
final class RawClient implements AutoCloseable {

    /** One received message: header and a copy of its body. */
    record Msg(PlayerHeader header, byte[] body) {
        XdrReader reader() {
            return new XdrReader(body, 0, body.length);
        }
    }

    final Socket socket;
    final InputStream in;
    final OutputStream out;
    final String banner;
    private final PlayerFrameReader frames = new PlayerFrameReader(32, 1 << 22);

    RawClient(int port) throws IOException {
        socket = new Socket(InetAddress.getLoopbackAddress(), port);
        socket.setSoTimeout(10_000);
        in = new BufferedInputStream(socket.getInputStream());
        out = socket.getOutputStream();
        byte[] b = in.readNBytes(32);
        banner = Banner.decode(b, b.length);
    }

    void send(int interf, int index, int type, int subtype, Consumer<XdrWriter> body) throws IOException {
        XdrWriter w = new XdrWriter();
        int at = PlayerCodec.beginMessage(w, DeviceAddress.of(interf, index), type, subtype, 0.0);
        body.accept(w);
        PlayerCodec.endMessage(w, at);
        out.write(w.array(), 0, w.size());
        out.flush();
    }

    void sendRaw(byte[] bytes) throws IOException {
        out.write(bytes);
        out.flush();
    }

    Msg read() throws IOException {
        PlayerHeader h = frames.read(in);
        XdrReader r = frames.body();
        byte[] body = new byte[h.size()];
        for (int i = 0; i < body.length; i += 4) {
            int v = r.readInt("body");
            body[i] = (byte) (v >>> 24);
            body[i + 1] = (byte) (v >>> 16);
            body[i + 2] = (byte) (v >>> 8);
            body[i + 3] = (byte) v;
        }
        return new Msg(h, body);
    }

    /** Reads until a reply (ACK or NACK) arrives; data and SYNCH seen on the way go to {@code seen}. */
    Msg reply(List<Msg> seen) throws IOException {
        while (true) {
            Msg m = read();
            int t = m.header().type();
            if (t == MessageType.RESP_ACK || t == MessageType.RESP_NACK) {
                return m;
            }
            seen.add(m);
        }
    }

    Msg request(int interf, int index, int subtype, Consumer<XdrWriter> body) throws IOException {
        send(interf, index, MessageType.REQ, subtype, body);
        return reply(new ArrayList<>());
    }

    /** Reads one PULL round after the ACK: the data up to (not including) the SYNCH. */
    List<Msg> round() throws IOException {
        List<Msg> data = new ArrayList<>();
        send(1, 0, MessageType.REQ, 4, w -> { });
        Msg ack = reply(data);
        if (ack.header().type() != MessageType.RESP_ACK) {
            throw new IOException("REQ DATA not acknowledged: " + ack.header());
        }
        while (true) {
            Msg m = read();
            if (m.header().type() == MessageType.SYNCH) {
                return data;
            }
            data.add(m);
        }
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
