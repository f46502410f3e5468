package io.rtaware.player.client;

import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;
import java.io.BufferedInputStream;
import java.io.Closeable;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.concurrent.TimeUnit;

/**
 * The TCP connection to one Player server: opens it and checks the banner (the handshake),
 * writes messages, and reads one framed message at a time with a wall-time limit. Counts the
 * bytes and messages in {@link PlayerCounters}; knows nothing of what the messages mean. Not
 * thread-safe: one thread owns it.
 */
final class PlayerConnection implements Closeable {

    private final String host;
    private final int port;
    private final PlayerCounters counters;
    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;
    private final String serverVersion;
    private final PlayerFrameReader frames;
    private final XdrWriter writer = new XdrWriter();

    private PlayerConnection(String host, int port, PlayerClientOptions options, PlayerCounters counters,
                             Socket socket, InputStream in, String serverVersion) throws IOException {
        this.host = host;
        this.port = port;
        this.counters = counters;
        this.socket = socket;
        this.in = in;
        this.out = socket.getOutputStream();
        this.serverVersion = serverVersion;
        this.frames = new PlayerFrameReader(Banner.SIZE_BYTES, options.maxBodyBytes());
    }

    /**
     * Connects and reads the banner.
     *
     * @throws PlayerConnectionException if the server cannot be reached in time
     * @throws PlayerProtocolException if the peer is not a Player server
     * @throws IOException on other I/O failures
     */
    static PlayerConnection open(String host, int port, PlayerClientOptions options, PlayerCounters counters)
            throws IOException {
        Socket socket = new Socket();
        try {
            socket.setTcpNoDelay(true);
            socket.connect(new InetSocketAddress(host, port), options.connectTimeoutMs());
        } catch (IOException e) {
            socket.close();
            throw new PlayerConnectionException("cannot connect to Player server " + host + ":" + port + " within "
                    + options.connectTimeoutMs() + " ms: " + e.getMessage(), e);
        }
        try {
            InputStream in = new BufferedInputStream(socket.getInputStream(), 65536);
            String version = readBanner(socket, in, host + ":" + port, options.connectTimeoutMs(), counters);
            PlayerConnection connection = new PlayerConnection(host, port, options, counters, socket, in, version);
            counters.connects++;
            counters.newConnection();
            return connection;
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
    }

    private static String readBanner(Socket socket, InputStream in, String server, int timeoutMs,
                                     PlayerCounters counters) throws IOException {
        byte[] banner = new byte[Banner.SIZE_BYTES];
        int n = 0;
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        try {
            while (n < banner.length) {
                long leftMs = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
                if (leftMs <= 0) {
                    throw new SocketTimeoutException();
                }
                socket.setSoTimeout((int) leftMs);
                int r = in.read(banner, n, banner.length - n);
                if (r < 0) {
                    break;
                }
                n += r;
                counters.bytesReceived += r;
            }
        } catch (SocketTimeoutException e) {
            if (n == 0) {
                throw new PlayerTimeoutException("no banner from " + server + " within " + timeoutMs
                        + " ms: the peer sent nothing (not a Player server?)");
            }
        }
        try {
            return Banner.decode(banner, n);
        } catch (PlayerProtocolException e) {
            counters.protocolErrors++;
            throw new PlayerProtocolException(0, "banner", server + " is not a Player server: received " + n
                    + " bytes " + Banner.printable(banner, n) + " instead of a 32-byte banner starting '"
                    + Banner.PREFIX + "'");
        }
    }

    /** @return the version the server announced */
    String serverVersion() {
        return serverVersion;
    }

    /** @return {@code host:port} */
    String server() {
        return host + ":" + port;
    }

    /** @return the server's port (libplayerc sends it as the robot field of device addresses) */
    int port() {
        return port;
    }

    /**
     * Starts a message in the connection's writer.
     *
     * @return the header's position, for {@link #send}
     */
    int begin(DeviceAddress dev, int type, int subtype) {
        writer.reset();
        return PlayerCodec.beginMessage(writer, dev, type, subtype, System.currentTimeMillis() / 1000.0);
    }

    /** @return the writer that holds the message begun with {@link #begin} */
    XdrWriter writer() {
        return writer;
    }

    /**
     * Completes the message begun with {@link #begin} and writes it.
     *
     * @throws PlayerConnectionException if the connection fails
     */
    void send(int headerAt) throws IOException {
        PlayerCodec.endMessage(writer, headerAt);
        try {
            out.write(writer.array(), 0, writer.size());
            out.flush();
        } catch (IOException e) {
            throw lost("sending to", e);
        }
        counters.messagesSent++;
        counters.bytesSent += writer.size();
    }

    /**
     * Reads one message, waiting at most {@code waitNs} of wall time.
     *
     * @return the header (the body is in {@link #body()} until the next read), or null if
     *     nothing complete arrived in time
     * @throws PlayerConnectionException if the server closed the connection or it failed
     * @throws PlayerProtocolException if the stream is broken
     */
    PlayerHeader readOne(long waitNs) throws IOException {
        long before = frames.bytesRead();
        try {
            socket.setSoTimeout((int) Math.max(1, Math.min(Integer.MAX_VALUE, TimeUnit.NANOSECONDS.toMillis(waitNs))));
            PlayerHeader h = frames.read(in);
            counters.messagesReceived++;
            return h;
        } catch (SocketTimeoutException e) {
            return null;
        } catch (EOFException e) {
            throw new PlayerConnectionException("Player server " + server() + " closed the connection", e);
        } catch (PlayerProtocolException e) {
            counters.protocolErrors++;
            throw e;
        } catch (IOException e) {
            throw lost("reading from", e);
        } finally {
            counters.bytesReceived += frames.bytesRead() - before;
        }
    }

    /** @return the body of the message last read */
    XdrReader body() {
        return frames.body();
    }

    /** @return bytes waiting in the socket */
    int available() throws IOException {
        try {
            return in.available();
        } catch (IOException e) {
            throw lost("reading from", e);
        }
    }

    private PlayerConnectionException lost(String what, IOException e) {
        return new PlayerConnectionException("connection to Player server " + server() + " lost while " + what
                + " it: " + e.getMessage(), e);
    }

    /** Closes the socket. Idempotent. */
    @Override
    public void close() throws IOException {
        socket.close();
    }
}
