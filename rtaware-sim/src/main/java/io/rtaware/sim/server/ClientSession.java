package io.rtaware.sim.server;

import io.rtaware.core.time.Clock;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import java.io.BufferedOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.lang.System.Logger.Level;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ThreadFactory;

/**
 * One connected client's connection: a reader thread that decodes messages and hands them to
 * the {@link Handler}, a writer thread that writes what the client's {@link ClientQueue} holds.
 * A client sending a malformed message, or part of a message and then nothing more within the
 * message timeout, is disconnected with one log line. Thread-safe.
 *
 * <p>Its two threads are plain threads, not {@link io.rtaware.core.agent.AgentThread}s: each
 * blocks in one socket call or queue wait for the connection's whole life, ends itself (and the
 * session) when the connection ends, and comes from the server's thread factory, through which
 * a client whose threads cannot be created is refused.
 */
final class ClientSession {

    private static final System.Logger LOG = System.getLogger(ClientSession.class.getName());

    /** Handles one decoded request or command. */
    interface Handler {
        void handle(ClientSession session, PlayerHeader header, XdrReader body) throws IOException;
    }

    /** How a session is made: the limits and collaborators every session shares. */
    record Settings(int queueLimit, int maxRequestBytes, int maxRules, long messageTimeoutNs, byte[] banner,
                    byte[] synchOk, Handler handler, ThreadFactory threads, Clock wallClock) {
    }

    private final Socket socket;
    private final String name;
    private final Settings settings;
    private final Runnable onClose;
    private final ClientQueue queue;
    private final PlayerFrameReader frames;
    private Thread reader;
    private Thread writer;
    private boolean ruleLimitLogged;

    /**
     * @param socket the connection
     * @param settings limits and collaborators
     * @param onClose run once when the session closes
     */
    ClientSession(Socket socket, Settings settings, Runnable onClose) {
        this.socket = socket;
        this.name = socket.getRemoteSocketAddress().toString();
        this.settings = settings;
        this.onClose = onClose;
        this.queue = new ClientQueue(settings.queueLimit(), settings.maxRules(), settings.banner(), settings.synchOk());
        this.frames = new PlayerFrameReader(0L, settings.maxRequestBytes());
    }

    /**
     * Creates and starts the writer and reader threads.
     *
     * @throws OutOfMemoryError if a thread cannot be created (the session is closed)
     * @throws RuntimeException if the thread factory fails (the session is closed)
     */
    void start() {
        try {
            writer = newThread(this::writeLoop, "rtaware-sim-write " + name);
            reader = newThread(this::readLoop, "rtaware-sim-read " + name);
            writer.start();
            reader.start();
        } catch (OutOfMemoryError | RuntimeException e) {
            close();
            throw e;
        }
    }

    private Thread newThread(Runnable body, String threadName) {
        Thread t = settings.threads().newThread(body);
        if (t == null) {
            throw new IllegalStateException("the thread factory made no thread for " + threadName);
        }
        t.setName(threadName);
        t.setDaemon(true);
        return t;
    }

    String name() {
        return name;
    }

    boolean subscribed(int deviceKey) {
        return queue.subscribed(deviceKey);
    }

    void subscribe(int deviceKey) {
        queue.subscribe(deviceKey);
    }

    void unsubscribe(int deviceKey) {
        queue.unsubscribe(deviceKey);
    }

    void setPull(boolean pullMode) {
        queue.setPull(pullMode);
    }

    /**
     * @param rule a validated rule
     * @return false if the client has as many rules as allowed (logged once per client)
     */
    boolean addRule(ReplaceRule rule) {
        if (queue.addRule(rule)) {
            return true;
        }
        synchronized (this) {
            if (ruleLimitLogged) {
                return false;
            }
            ruleLimitLogged = true;
        }
        LOG.log(Level.WARNING, "rtaware-sim: client " + name + " reached " + settings.maxRules()
                + " replace rules, the limit per client (sim --max-rules); further rules are NACKed");
        return false;
    }

    /** Queues a reply; a client that leaves too many replies unread is disconnected. */
    void reply(byte[] message) {
        if (queue.reply(message)) {
            LOG.log(Level.WARNING, "rtaware-sim: disconnecting client " + name + ": more than "
                    + (settings.queueLimit() + ClientQueue.REPLY_SLACK) + " messages unread");
            close();
        }
    }

    /** @see ClientQueue#pullRound(byte[]) */
    void pullRound(byte[] ack) {
        queue.pullRound(ack);
    }

    /** Called by the stepping thread with the messages one world step published. */
    void deliver(List<Outgoing> batch) {
        queue.deliver(batch);
    }

    private void readLoop() {
        try { // the stream is closed with the socket by close(), after the reason is logged
            MessageTimeoutInputStream in = new MessageTimeoutInputStream(socket.getInputStream(),
                    socket::setSoTimeout, settings.wallClock(), settings.messageTimeoutNs());
            while (!queue.isClosed()) {
                PlayerHeader h = frames.read(in);
                in.messageComplete();
                settings.handler().handle(this, h, frames.body());
            }
        } catch (PlayerProtocolException e) {
            LOG.log(Level.WARNING, "rtaware-sim: disconnecting client " + name + ": " + e.getMessage());
        } catch (SocketTimeoutException e) {
            LOG.log(Level.WARNING, "rtaware-sim: disconnecting client " + name + ": a message did not complete within "
                    + settings.messageTimeoutNs() / 1_000_000 + " ms of its first bytes (sim --message-timeout)");
        } catch (EOFException e) {
            LOG.log(Level.DEBUG, "rtaware-sim: client " + name + " closed the connection");
        } catch (IOException e) {
            if (!queue.isClosed()) {
                LOG.log(Level.INFO, "rtaware-sim: client " + name + " lost: " + e.getMessage());
            }
        } finally {
            close();
        }
    }

    private void writeLoop() {
        List<Outgoing> batch = new ArrayList<>();
        try (OutputStream out = new BufferedOutputStream(socket.getOutputStream(), 1 << 16)) {
            while (queue.take(batch)) {
                for (Outgoing m : batch) {
                    out.write(m.bytes());
                }
                batch.clear();
                out.flush();
            }
        } catch (IOException e) {
            if (!queue.isClosed()) {
                LOG.log(Level.INFO, "rtaware-sim: cannot write to client " + name + ": " + e.getMessage());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            close();
        }
    }

    /** Closes the connection; idempotent. */
    void close() {
        if (!queue.close()) {
            return;
        }
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.DEBUG, "rtaware-sim: closing " + name + ": " + e.getMessage());
        }
        onClose.run();
    }
}
