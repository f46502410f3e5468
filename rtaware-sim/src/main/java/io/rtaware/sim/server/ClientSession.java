package io.rtaware.sim.server;

import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.lang.System.Logger.Level;
import java.net.Socket;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * One connected client: a reader thread that decodes requests and hands them to the server,
 * a writer thread that writes queued messages, and the client's queues. Data is filtered by
 * subscription, held until {@code REQ DATA} in PULL mode, replaced per the client's replace
 * rules, and bounded: beyond the queue limit the oldest queued data message is dropped, so
 * the sim thread never waits for a slow client. Thread-safe (queues are guarded by this
 * object's monitor; subscriptions are a concurrent set).
 */
final class ClientSession {

    private static final System.Logger LOG = System.getLogger(ClientSession.class.getName());
    /** Replies beyond the data limit a client may leave unread before it is dropped. */
    private static final int REPLY_SLACK = 1024;

    /** A message ready to write, with the address fields replace rules look at. */
    record Outgoing(byte[] bytes, int interf, int index, int type, int subtype) {
    }

    /** Handles one decoded request or command. */
    interface Handler {
        void handle(ClientSession session, PlayerHeader header, XdrReader body) throws IOException;
    }

    private final Socket socket;
    private final String name;
    private final int queueLimit;
    private final Handler handler;
    private final Runnable onClose;
    private final PlayerFrameReader frames;
    private final Set<Integer> subscriptions = ConcurrentHashMap.newKeySet();
    private final ArrayDeque<Outgoing> outbox = new ArrayDeque<>();
    private final ArrayDeque<Outgoing> held = new ArrayDeque<>();
    private final List<ReplaceRule> rules = new ArrayList<>();
    private final byte[] synchOk;
    private final Thread reader;
    private final Thread writer;
    private boolean pull;
    private boolean roundOwed;
    private long dropped;
    private boolean closed;

    ClientSession(Socket socket, int queueLimit, int maxRequestBytes, byte[] banner, byte[] synchOk,
                  Handler handler, Runnable onClose) {
        this.socket = socket;
        this.name = socket.getRemoteSocketAddress().toString();
        this.queueLimit = queueLimit;
        this.handler = handler;
        this.onClose = onClose;
        this.synchOk = synchOk;
        this.frames = new PlayerFrameReader(0L, maxRequestBytes);
        this.outbox.add(new Outgoing(banner, 0, 0, 0, 0));
        this.reader = new Thread(this::readLoop, "rtaware-sim-read " + name);
        this.writer = new Thread(this::writeLoop, "rtaware-sim-write " + name);
        reader.setDaemon(true);
        writer.setDaemon(true);
    }

    void start() {
        writer.start();
        reader.start();
    }

    String name() {
        return name;
    }

    boolean subscribed(int deviceKey) {
        return subscriptions.contains(deviceKey);
    }

    void subscribe(int deviceKey) {
        subscriptions.add(deviceKey);
    }

    void unsubscribe(int deviceKey) {
        subscriptions.remove(deviceKey);
    }

    synchronized void setPull(boolean pullMode) {
        if (this.pull && !pullMode) {
            while (!held.isEmpty()) {
                outbox.add(held.poll());
            }
            roundOwed = false;
            notifyAll();
        }
        this.pull = pullMode;
    }

    synchronized void addRule(ReplaceRule rule) {
        rules.add(rule);
    }

    /** Queues a reply; a client that leaves too many replies unread is disconnected. */
    void reply(byte[] message) {
        boolean overflow;
        synchronized (this) {
            if (closed) {
                return;
            }
            outbox.add(new Outgoing(message, 0, 0, 0, 0));
            overflow = outbox.size() > queueLimit + REPLY_SLACK;
            notifyAll();
        }
        if (overflow) {
            LOG.log(Level.WARNING, "rtaware-sim: disconnecting client " + name + ": more than "
                    + (queueLimit + REPLY_SLACK) + " messages unread");
            close();
        }
    }

    /**
     * The ACK of REQ DATA, then (in PULL mode) the held round and a SYNCH, or the SYNCH after
     * the next data if nothing is held. In PUSH mode only the ACK.
     */
    synchronized void pullRound(byte[] ack) {
        if (closed) {
            return;
        }
        outbox.add(new Outgoing(ack, 0, 0, 0, 0));
        if (!pull) {
            notifyAll();
            return;
        }
        if (held.isEmpty()) {
            roundOwed = true;
        } else {
            releaseRound();
        }
        notifyAll();
    }

    /** Called by the sim thread with the messages one world step published. */
    synchronized void deliver(List<Outgoing> batch, int[] deviceKeys) {
        if (closed) {
            return;
        }
        boolean any = false;
        for (int i = 0; i < batch.size(); i++) {
            if (!subscriptions.contains(deviceKeys[i])) {
                continue;
            }
            any = true;
            enqueueData(pull ? held : outbox, batch.get(i));
        }
        if (any && pull && roundOwed) {
            releaseRound();
        }
        if (any) {
            notifyAll();
        }
    }

    private void releaseRound() {
        while (!held.isEmpty()) {
            outbox.add(held.poll());
        }
        if (dropped > 0) {
            outbox.add(new Outgoing(PlayerSimServer.synchOverflow(dropped), 0, 0, 0, 0));
            dropped = 0;
        } else {
            outbox.add(new Outgoing(synchOk, 0, 0, 0, 0));
        }
        roundOwed = false;
    }

    private void enqueueData(ArrayDeque<Outgoing> queue, Outgoing m) {
        int replace = Subtypes.REPLACE_ACCEPT;
        for (int i = rules.size() - 1; i >= 0; i--) {
            ReplaceRule r = rules.get(i);
            if ((r.interf() < 0 || r.interf() == m.interf()) && (r.index() < 0 || r.index() == m.index())
                    && (r.type() < 0 || r.type() == m.type()) && (r.subtype() < 0 || r.subtype() == m.subtype())) {
                replace = r.replace();
                break;
            }
        }
        if (replace == Subtypes.REPLACE_IGNORE) {
            return;
        }
        int data = 0;
        for (Iterator<Outgoing> it = queue.iterator(); it.hasNext(); ) {
            Outgoing q = it.next();
            if (q.type() != MessageType.DATA) {
                continue;
            }
            if (replace == Subtypes.REPLACE_REPLACE && q.interf() == m.interf() && q.index() == m.index()
                    && q.subtype() == m.subtype()) {
                it.remove();
            } else {
                data++;
            }
        }
        if (data >= queueLimit) {
            for (Iterator<Outgoing> it = queue.iterator(); it.hasNext(); ) {
                if (it.next().type() == MessageType.DATA) {
                    it.remove();
                    dropped++;
                    break;
                }
            }
        }
        queue.add(m);
    }

    private void readLoop() {
        try (InputStream in = new BufferedInputStream(socket.getInputStream())) {
            while (!isClosed()) {
                PlayerHeader h = frames.read(in);
                handler.handle(this, h, frames.body());
            }
        } catch (PlayerProtocolException e) {
            LOG.log(Level.WARNING, "rtaware-sim: disconnecting client " + name + ": " + e.getMessage());
        } catch (EOFException e) {
            LOG.log(Level.DEBUG, "rtaware-sim: client " + name + " closed the connection");
        } catch (IOException e) {
            if (!isClosed()) {
                LOG.log(Level.INFO, "rtaware-sim: client " + name + " lost: " + e.getMessage());
            }
        } finally {
            close();
        }
    }

    private void writeLoop() {
        List<Outgoing> batch = new ArrayList<>();
        try (OutputStream out = new BufferedOutputStream(socket.getOutputStream(), 1 << 16)) {
            while (true) {
                synchronized (this) {
                    while (outbox.isEmpty() && !closed) {
                        wait();
                    }
                    if (closed) {
                        return;
                    }
                    batch.addAll(outbox);
                    outbox.clear();
                }
                for (Outgoing m : batch) {
                    out.write(m.bytes());
                }
                batch.clear();
                out.flush();
            }
        } catch (IOException e) {
            if (!isClosed()) {
                LOG.log(Level.INFO, "rtaware-sim: cannot write to client " + name + ": " + e.getMessage());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            close();
        }
    }

    synchronized boolean isClosed() {
        return closed;
    }

    /** Closes the connection; idempotent. */
    void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
            outbox.clear();
            held.clear();
            notifyAll();
        }
        subscriptions.clear();
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.DEBUG, "rtaware-sim: closing " + name + ": " + e.getMessage());
        }
        onClose.run();
    }

    void join(long millis) throws InterruptedException {
        reader.join(millis);
        writer.join(millis);
    }
}
