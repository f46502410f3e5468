package io.rtaware.app.run;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A TCP proxy between a Player client and server on loopback that, once {@link #poison()} was
 * called, replaces the x of every position2d DATA STATE the server sends with NaN, as the
 * hostile proxy of issue 12 did; and, once {@link #blindLaser()} was called, every range of
 * every laser DATA SCAN with 0 (a laser blinded by something against it, issue 24).
 * Client-to-server bytes pass unchanged. For tests.
 */
final class PoisoningProxy implements AutoCloseable {

    private static final int BANNER_BYTES = 32;
    private static final int HEADER_BYTES = 40;
    private static final int POSITION2D = 4;
    private static final int DATA = 1;
    private static final int DATA_STATE = 1;
    private static final int LASER = 6;
    private static final int DATA_SCAN = 1;
    /** Offset of the first range in a laser DATA SCAN body: four floats, the count, the XDR array length. */
    private static final int FIRST_RANGE = 24;

    private final ServerSocket listener;
    private final int upstreamPort;
    private final List<Socket> sockets = new CopyOnWriteArrayList<>();
    private final AtomicLong poisoned = new AtomicLong();
    private volatile boolean poisoning;
    private volatile boolean blinding;
    private final AtomicLong blinded = new AtomicLong();

    PoisoningProxy(int upstreamPort) throws IOException {
        this.upstreamPort = upstreamPort;
        this.listener = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        Thread accept = new Thread(this::acceptLoop, "poisoning-proxy");
        accept.setDaemon(true);
        accept.start();
    }

    int port() {
        return listener.getLocalPort();
    }

    /** From now on every position2d state carries x = NaN. */
    void poison() {
        poisoning = true;
    }

    /** From now on every laser range reads 0 m. */
    void blindLaser() {
        blinding = true;
    }

    /** @return laser scans blinded so far */
    long blinded() {
        return blinded.get();
    }

    /** @return position2d states poisoned so far */
    long poisoned() {
        return poisoned.get();
    }

    private void acceptLoop() {
        while (!listener.isClosed()) {
            try {
                Socket client = listener.accept();
                Socket server = new Socket();
                server.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), upstreamPort));
                client.setTcpNoDelay(true);
                server.setTcpNoDelay(true);
                sockets.add(client);
                sockets.add(server);
                start(() -> pipe(client.getInputStream(), server.getOutputStream()));
                start(() -> rewrite(server.getInputStream(), client.getOutputStream()));
            } catch (IOException e) {
                return;
            }
        }
    }

    private interface Io {
        void run() throws IOException;
    }

    private static void start(Io io) {
        Thread t = new Thread(() -> {
            try {
                io.run();
            } catch (IOException ignored) {
                // one side closed: the other follows when the test closes the proxy
            }
        }, "poisoning-proxy-pipe");
        t.setDaemon(true);
        t.start();
    }

    private static void pipe(InputStream in, OutputStream out) throws IOException {
        byte[] buf = new byte[8192];
        for (int n; (n = in.read(buf)) >= 0; ) {
            out.write(buf, 0, n);
            out.flush();
        }
        out.close();
    }

    private void rewrite(InputStream raw, OutputStream out) throws IOException {
        DataInputStream in = new DataInputStream(raw);
        byte[] banner = new byte[BANNER_BYTES];
        in.readFully(banner);
        out.write(banner);
        byte[] header = new byte[HEADER_BYTES];
        while (true) {
            in.readFully(header);
            ByteBuffer h = ByteBuffer.wrap(header);
            int size = h.getInt(36);
            byte[] body = new byte[size];
            in.readFully(body);
            if (poisoning && h.getInt(8) == POSITION2D && h.getInt(16) == DATA && h.getInt(20) == DATA_STATE
                    && size >= 8) {
                ByteBuffer.wrap(body).putDouble(0, Double.NaN);
                poisoned.incrementAndGet();
            }
            if (blinding && h.getInt(8) == LASER && h.getInt(16) == DATA && h.getInt(20) == DATA_SCAN
                    && size >= FIRST_RANGE) {
                ByteBuffer b = ByteBuffer.wrap(body);
                int ranges = b.getInt(16);
                for (int i = 0; i < ranges && FIRST_RANGE + 4 * i + 4 <= size; i++) {
                    b.putFloat(FIRST_RANGE + 4 * i, 0f);
                }
                blinded.incrementAndGet();
            }
            out.write(header);
            out.write(body);
            out.flush();
        }
    }

    @Override
    public void close() throws IOException {
        listener.close();
        for (Socket s : sockets) {
            s.close();
        }
    }
}
