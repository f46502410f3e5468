package io.rtaware.live;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import io.rtaware.core.agent.ThreadNames;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * The live view's HTTP server, on the JDK's built-in {@link HttpServer}. Serves:
 * <ul>
 *   <li>{@code /}: the page (static HTML with its script and style inline);</li>
 *   <li>{@code /snapshot.json}: the latest snapshot;</li>
 *   <li>{@code /events}: Server-Sent Events, one {@code data:} line per snapshot;</li>
 *   <li>resources put with {@link #putResource} (e.g. {@code /world.png});</li>
 *   <li>404 for any other path, 405 for methods other than GET and HEAD.</li>
 * </ul>
 * Each event-stream client has a slot holding at most one snapshot, the newest: a slow browser
 * gets dropped updates, never a growing queue, and {@link #publish} never blocks. A client whose
 * connection fails is removed. Streams get a comment line every {@value #KEEPALIVE_MS} ms when
 * nothing new came, so a closed browser is noticed after the run too.
 *
 * <p>Its threads are the JDK server's dispatcher and an executor that gives each exchange (an
 * event stream for its whole life) a thread, not loops of ours, so they are not
 * {@link io.rtaware.core.agent.AgentThread}s; {@link #close()} stops both.
 *
 * <p>Thread-safe: {@link #publish} and {@link #putResource} from any thread.
 */
public final class LiveServer implements AutoCloseable {

    /** Event-stream clients served at once; more get 503. */
    public static final int MAX_EVENT_CLIENTS = 16;
    static final long KEEPALIVE_MS = 2_000;
    private static final byte[] KEEPALIVE = ": keepalive\n\n".getBytes(StandardCharsets.US_ASCII);

    /** A static response body. */
    private record Resource(String contentType, byte[] body) {
    }

    private final HttpServer server;
    private final ExecutorService executor;
    private final Map<String, Resource> resources = new ConcurrentHashMap<>();
    private final CopyOnWriteArrayList<EventClient> clients = new CopyOnWriteArrayList<>();
    /** One permit per stream slot: taking it is the admission, so concurrent connects cannot overshoot. */
    private final Semaphore eventSlots = new Semaphore(MAX_EVENT_CLIENTS);
    private final AtomicInteger clientsEver = new AtomicInteger();
    private volatile byte[] snapshot = "{}".getBytes(StandardCharsets.UTF_8);
    private volatile boolean closed;

    /**
     * Starts serving.
     *
     * @param address where to listen (port 0 for a free one)
     * @param page the page served at {@code /}
     * @throws IOException if the address cannot be bound
     */
    public LiveServer(InetSocketAddress address, byte[] page) throws IOException {
        resources.put("/", new Resource("text/html; charset=utf-8", page.clone()));
        AtomicInteger threads = new AtomicInteger();
        executor = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, ThreadNames.LIVE_HTTP_PREFIX + threads.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        server = HttpServer.create(address, 0);
        server.setExecutor(executor);
        server.createContext("/", this::handle);
        server.start();
    }

    /** @return the port listened on */
    public int port() {
        return server.getAddress().getPort();
    }

    /**
     * Makes {@code json} the latest snapshot and offers it to every event-stream client,
     * replacing what a client has not sent yet. Never blocks.
     *
     * @param json one snapshot, UTF-8 JSON without line breaks
     */
    public void publish(byte[] json) {
        snapshot = json;
        for (EventClient client : clients) {
            client.offer(json);
        }
    }

    /**
     * Serves {@code body} at {@code path} from now on, replacing what was there.
     *
     * @param path absolute path, e.g. {@code /world.png}
     * @param contentType the MIME type
     * @param body the bytes (not copied: do not change them afterwards)
     */
    public void putResource(String path, String contentType, byte[] body) {
        if (!path.startsWith("/") || path.equals("/")) {
            throw new IllegalArgumentException("resource path must start with / and name something: " + path);
        }
        resources.put(path, new Resource(contentType, body));
    }

    /** @return event-stream clients connected now */
    public int eventClients() {
        return clients.size();
    }

    /** @return event-stream clients accepted since the start */
    public int eventClientsEver() {
        return clientsEver.get();
    }

    /** @return bytes waiting in the clients' slots (at most one snapshot each) */
    long bufferedBytes() {
        long sum = 0;
        for (EventClient client : clients) {
            byte[] pending = client.slot.get();
            sum += pending == null ? 0 : pending.length;
        }
        return sum;
    }

    private void handle(HttpExchange exchange) throws IOException {
        try (exchange) {
            String method = exchange.getRequestMethod();
            boolean head = method.equals("HEAD");
            if (!head && !method.equals("GET")) {
                exchange.getResponseHeaders().set("Allow", "GET, HEAD");
                send(exchange, 405, "text/plain; charset=utf-8", "method not allowed\n".getBytes(StandardCharsets.UTF_8),
                        false);
                return;
            }
            String path = exchange.getRequestURI().getPath();
            if (path.equals("/events") && !head) {
                stream(exchange);
                return;
            }
            Resource resource = path.equals("/snapshot.json")
                    ? new Resource("application/json", snapshot) : resources.get(path);
            if (resource == null) {
                send(exchange, 404, "text/plain; charset=utf-8",
                        ("not found: " + path + "\n").getBytes(StandardCharsets.UTF_8), head);
                return;
            }
            send(exchange, 200, resource.contentType(), resource.body(), head);
        }
    }

    private static void send(HttpExchange exchange, int status, String contentType, byte[] body, boolean head)
            throws IOException {
        exchange.getResponseHeaders().set("Content-Type", contentType);
        exchange.getResponseHeaders().set("Cache-Control", "no-store");
        if (head) {
            exchange.sendResponseHeaders(status, -1);
            return;
        }
        exchange.sendResponseHeaders(status, body.length);
        exchange.getResponseBody().write(body);
    }

    /** Serves one event stream on this handler thread until the client goes or the server closes. */
    private void stream(HttpExchange exchange) throws IOException {
        if (closed || !eventSlots.tryAcquire()) {
            send(exchange, 503, "text/plain; charset=utf-8",
                    "too many live view clients\n".getBytes(StandardCharsets.UTF_8), false);
            return;
        }
        EventClient client = new EventClient(Thread.currentThread());
        try {
            exchange.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
            exchange.getResponseHeaders().set("Cache-Control", "no-store");
            exchange.sendResponseHeaders(200, 0);
            client.offer(snapshot);
            clients.add(client);
            clientsEver.incrementAndGet();
            OutputStream body = exchange.getResponseBody();
            while (!closed) {
                byte[] next = client.slot.getAndSet(null);
                if (next == null) {
                    LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(KEEPALIVE_MS));
                    if (client.slot.get() == null && !closed) {
                        body.write(KEEPALIVE);
                        body.flush();
                    }
                    continue;
                }
                body.write(DATA);
                body.write(next);
                body.write(END);
                body.flush();
            }
        } catch (IOException gone) {
            // The browser went away: drop it below.
        } finally {
            clients.remove(client);
            eventSlots.release();
        }
    }

    private static final byte[] DATA = "data: ".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] END = "\n\n".getBytes(StandardCharsets.US_ASCII);

    /** One event-stream client: a latest-value slot and the thread that drains it. */
    private static final class EventClient {
        final AtomicReference<byte[]> slot = new AtomicReference<>();
        private final Thread writer;

        EventClient(Thread writer) {
            this.writer = writer;
        }

        void offer(byte[] json) {
            slot.set(json);
            LockSupport.unpark(writer);
        }
    }

    /** Stops listening and ends every event stream. */
    @Override
    public void close() {
        closed = true;
        clients.forEach(c -> LockSupport.unpark(c.writer));
        server.stop(0);
        executor.shutdownNow();
    }
}
