package io.rtaware.sim.server;

import java.io.IOException;
import java.lang.System.Logger.Level;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.agrona.concurrent.Agent;

/**
 * The accept loop and client admission. A failing accept (e.g. no file descriptors left) is
 * retried after a bounded exponential back-off ({@value #FIRST_BACKOFF_NS} ns doubling up to
 * {@value #MAX_BACKOFF_NS} ns), logged once when it starts and once when accepting works again.
 * At most {@code maxClients} clients are connected (each costs two threads); a client beyond the
 * limit, or one whose threads cannot be created, is refused: its socket is closed and the next
 * connection is served. Refusals are logged once per episode too. An {@link Agent} whose duty
 * cycle accepts one connection, blocking in {@link ServerSocket#accept()} (run by an
 * {@link io.rtaware.core.agent.AgentThread}); {@link #stop()} and closing the server socket end
 * it.
 */
final class ClientAcceptor implements Agent {

    private static final System.Logger LOG = System.getLogger(ClientAcceptor.class.getName());

    /** The first back-off after a failed accept: 1 ms. */
    static final long FIRST_BACKOFF_NS = 1_000_000L;
    /** The longest back-off: 1 s. */
    static final long MAX_BACKOFF_NS = 1_000_000_000L;

    /** Makes the session of an admitted connection. */
    interface SessionFactory {
        ClientSession create(Socket socket, Runnable onClose);
    }

    private final ServerSocket serverSocket;
    private final ServerEnvironment env;
    private final int maxClients;
    private final SessionFactory sessionFactory;
    private final CopyOnWriteArrayList<ClientSession> sessions = new CopyOnWriteArrayList<>();
    private final FailureEpisode acceptFailures = new FailureEpisode(LOG);
    private final FailureEpisode refusedFull = new FailureEpisode(LOG);
    private final FailureEpisode refusedNoThreads = new FailureEpisode(LOG);
    private volatile boolean running = true;
    /** Back-off before the next accept after a failed one, ns (the accepting thread only). */
    private long backoffNs;

    /**
     * @param serverSocket the bound socket
     * @param env how to accept and wait
     * @param maxClients most clients connected at once, positive
     * @param sessionFactory makes a session for an admitted connection
     */
    ClientAcceptor(ServerSocket serverSocket, ServerEnvironment env, int maxClients, SessionFactory sessionFactory) {
        this.serverSocket = serverSocket;
        this.env = env;
        this.maxClients = maxClients;
        this.sessionFactory = sessionFactory;
    }

    /** @return the connected clients (a live, thread-safe view) */
    List<ClientSession> sessions() {
        return sessions;
    }

    @Override
    public String roleName() {
        return "rtaware-sim-accept :" + serverSocket.getLocalPort();
    }

    /** Accepts one connection and admits or refuses it; a failed accept backs off. */
    @Override
    public int doWork() {
        if (!running) {
            return 0;
        }
        Socket socket;
        try {
            socket = env.accept().accept(serverSocket);
        } catch (IOException e) {
            if (!running) {
                return 0;
            }
            backoffNs = backoffNs == 0 ? FIRST_BACKOFF_NS : Math.min(MAX_BACKOFF_NS, 2 * backoffNs);
            long pauseNs = backoffNs;
            acceptFailures.failed(() -> "rtaware-sim: accept failed: " + e.getMessage()
                    + "; retrying with back-off up to " + MAX_BACKOFF_NS / 1_000_000 + " ms (logged again when it works)");
            try {
                env.pause().pause(pauseNs);
            } catch (InterruptedException stop) {
                Thread.currentThread().interrupt(); // closing: the loop ends
            }
            return 0;
        }
        backoffNs = 0;
        acceptFailures.ended(n -> "rtaware-sim: accepting clients again after " + n + " failed accepts");
        admit(socket);
        return 1;
    }

    private void admit(Socket socket) {
        String peer = String.valueOf(socket.getRemoteSocketAddress());
        if (!running) {
            closeQuietly(socket);
            return;
        }
        if (sessions.size() >= maxClients) {
            refusedFull.failed(() -> "rtaware-sim: refusing client " + peer + ": " + maxClients
                    + " clients connected, the limit (sim --max-clients); further refusals are logged when one is admitted");
            closeQuietly(socket);
            return;
        }
        refusedFull.ended(n -> "rtaware-sim: admitting clients again, after " + n
                + " were refused at the limit of " + maxClients);
        try {
            socket.setTcpNoDelay(true);
        } catch (SocketException e) {
            LOG.log(Level.DEBUG, "rtaware-sim: TCP_NODELAY: " + e.getMessage());
        }
        ClientSession[] holder = new ClientSession[1];
        ClientSession session = sessionFactory.create(socket, () -> sessions.remove(holder[0]));
        holder[0] = session;
        sessions.add(session);
        if (!running) {
            session.close();
            return;
        }
        try {
            session.start();
        } catch (OutOfMemoryError | RuntimeException e) {
            // start() closed the session (and so removed it)
            refusedNoThreads.failed(() -> "rtaware-sim: refusing client " + peer + ": cannot start its threads ("
                    + e + "); serving the next client");
            return;
        }
        refusedNoThreads.ended(n -> "rtaware-sim: client threads start again, after " + n + " clients were refused");
        LOG.log(Level.DEBUG, "rtaware-sim: client " + session.name() + " connected");
    }

    /** Stops accepting (the caller closes the server socket and interrupts the thread) and closes every client. */
    void stop() {
        running = false;
        for (ClientSession s : sessions) {
            s.close();
        }
    }

    private static void closeQuietly(Socket socket) {
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.DEBUG, "rtaware-sim: closing a refused connection: " + e.getMessage());
        }
    }
}
