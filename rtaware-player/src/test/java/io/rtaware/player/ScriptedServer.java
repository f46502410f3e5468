package io.rtaware.player;

import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/** A one-connection TCP server on 127.0.0.1 that runs a script, for client tests. */
public final class ScriptedServer implements AutoCloseable {

    /** What the server does with its one connection. */
    @FunctionalInterface
    public interface Script {
        /**
         * @param conn the accepted connection
         * @throws Exception on failure (reported by {@link #await})
         */
        void run(Conn conn) throws Exception;
    }

    /** The accepted connection with helpers. */
    public static final class Conn {
        private final Socket socket;
        private final InputStream in;
        private final OutputStream out;
        private final PlayerFrameReader frames = new PlayerFrameReader(0, PlayerFrameReader.DEFAULT_MAX_BODY_BYTES);
        private final Random random = new Random(42);
        private int maxChunk = Integer.MAX_VALUE;

        Conn(Socket socket) throws IOException {
            this.socket = socket;
            socket.setTcpNoDelay(true);
            this.in = socket.getInputStream();
            this.out = socket.getOutputStream();
        }

        /** @param bytes largest write; 1 sends byte by byte, other values random chunks up to it */
        public void chunks(int bytes) {
            maxChunk = bytes;
        }

        /** Sends the standard banner. */
        public void banner() throws IOException {
            send(Banner.encode("3.1.1-dev"));
        }

        /** @param data bytes to send, in chunks as configured */
        public void send(byte[] data) throws IOException {
            send(data, 0, data.length);
        }

        /**
         * @param data source
         * @param off first byte
         * @param len how many
         */
        public void send(byte[] data, int off, int len) throws IOException {
            int end = off + len;
            while (off < end) {
                int n = maxChunk == Integer.MAX_VALUE ? end - off
                        : Math.min(end - off, maxChunk == 1 ? 1 : 1 + random.nextInt(maxChunk));
                out.write(data, off, n);
                out.flush();
                off += n;
            }
        }

        /** @return the next message from the client: header and body bytes */
        public byte[] readMessage() throws IOException {
            frames.read(in);
            return frames.copyMessage();
        }

        /** @return true if the client closed its end (reads end of stream) */
        public boolean clientClosed() throws IOException {
            socket.setSoTimeout(5000);
            try {
                frames.read(in);
                return false;
            } catch (java.io.EOFException e) {
                return true;
            }
        }

        /** Closes the connection. */
        public void close() throws IOException {
            socket.close();
        }
    }

    private final ServerSocket server;
    private final CompletableFuture<Void> done = new CompletableFuture<>();

    /**
     * Starts listening and runs the script on the first connection, in a daemon thread.
     *
     * @param script what to do
     * @throws IOException if the port cannot be opened
     */
    public ScriptedServer(Script script) throws IOException {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        Thread t = new Thread(() -> {
            try (Socket s = server.accept()) {
                script.run(new Conn(s));
                done.complete(null);
            } catch (Throwable e) {
                done.completeExceptionally(e);
            }
        }, "scripted-player-server");
        t.setDaemon(true);
        t.start();
    }

    /** @return the port on 127.0.0.1 */
    public int port() {
        return server.getLocalPort();
    }

    /** Waits for the script to finish and rethrows its failure. */
    public void await() throws Exception {
        try {
            done.get(20, TimeUnit.SECONDS);
        } catch (java.util.concurrent.ExecutionException e) {
            if (e.getCause() instanceof Exception ex) {
                throw ex;
            }
            throw e;
        }
    }

    @Override
    public void close() throws IOException {
        server.close();
    }

    /**
     * @param a bytes
     * @param b bytes
     * @return true if equal apart from host, robot (bytes 0-7) and timestamp (24-31)
     */
    public static boolean sameIgnoringHostRobotTime(byte[] a, byte[] b) {
        if (a.length != b.length || a.length < PlayerHeader.SIZE_BYTES) {
            return false;
        }
        byte[] x = a.clone();
        byte[] y = b.clone();
        for (int i : new int[] {0, 1, 2, 3, 4, 5, 6, 7, 24, 25, 26, 27, 28, 29, 30, 31}) {
            x[i] = 0;
            y[i] = 0;
        }
        return Arrays.equals(x, y);
    }
}
