package io.rtaware.foxglove;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayOutputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A WebSocket client for the tests, on the JDK's own {@link HttpClient} WebSocket (not ours): it
 * offers the Foxglove subprotocol and queues each whole message, text as {@link String}, binary
 * as {@code byte[]}; Time frames (the server's clock) go to a queue of their own, as a client's
 * timeline takes them apart from the data. While paused it asks the JDK for no more messages, so
 * it stops reading the socket: a slow client.
 */
final class WsClient implements WebSocket.Listener, AutoCloseable {

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final long WAIT_S = 20;

    private final BlockingQueue<Object> messages = new LinkedBlockingQueue<>();
    private final BlockingQueue<Long> times = new LinkedBlockingQueue<>();
    private final StringBuilder text = new StringBuilder();
    private final ByteArrayOutputStream binary = new ByteArrayOutputStream();
    private volatile boolean paused;
    private volatile WebSocket socket;
    private volatile int closeCode = -1;
    private final CountDownLatch closed = new CountDownLatch(1);

    /** Connects, offering {@value FoxgloveProtocol#SUBPROTOCOL}. */
    static WsClient connect(String url) throws Exception {
        return connect(url, FoxgloveProtocol.SUBPROTOCOL);
    }

    /** Connects, offering these subprotocols in this order. */
    static WsClient connect(String url, String first, String... more) throws Exception {
        WsClient client = new WsClient();
        client.socket = HttpClient.newHttpClient().newWebSocketBuilder().subprotocols(first, more)
                .buildAsync(URI.create(url), client).get(WAIT_S, TimeUnit.SECONDS);
        return client;
    }

    WebSocket socket() {
        return socket;
    }

    void send(String json) throws Exception {
        socket.sendText(json, true).get(WAIT_S, TimeUnit.SECONDS);
    }

    /** Stops asking for messages: the JDK stops reading the socket. */
    void pause() {
        paused = true;
    }

    /** Asks for messages again. */
    void resume() {
        paused = false;
        socket.request(1);
    }

    /** @return the next whole message, text or binary */
    Object next() throws InterruptedException {
        Object m = messages.poll(WAIT_S, TimeUnit.SECONDS);
        if (m == null) {
            throw new AssertionError("no message within " + WAIT_S + " s");
        }
        return m;
    }

    /** @return the next message, which must be JSON text */
    JsonNode nextJson() throws Exception {
        Object m = next();
        if (!(m instanceof String s)) {
            throw new AssertionError("expected a text message, got " + ((byte[]) m).length + " binary bytes");
        }
        return MAPPER.readTree(s);
    }

    /** @return the next message, which must be binary */
    byte[] nextBinary() throws Exception {
        Object m = next();
        if (!(m instanceof byte[] b)) {
            throw new AssertionError("expected a binary message, got " + m);
        }
        return b;
    }

    /** @return the next Time frame's timestamp, ns */
    long nextTime() throws InterruptedException {
        Long t = times.poll(WAIT_S, TimeUnit.SECONDS);
        if (t == null) {
            throw new AssertionError("no Time frame within " + WAIT_S + " s");
        }
        return t;
    }

    /** @return Time frames received and not taken yet */
    int queuedTimes() {
        return times.size();
    }

    /** @return messages received and not taken yet */
    int queued() {
        return messages.size();
    }

    /** @return the close code the server sent, waiting for its Close message */
    int awaitCloseCode() throws InterruptedException {
        if (!closed.await(WAIT_S, TimeUnit.SECONDS)) {
            throw new AssertionError("no Close message within " + WAIT_S + " s");
        }
        return closeCode;
    }

    @Override
    public void onOpen(WebSocket webSocket) {
        webSocket.request(1);
    }

    @Override
    public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
        text.append(data);
        if (last) {
            messages.add(text.toString());
            text.setLength(0);
        }
        more(webSocket);
        return null;
    }

    @Override
    public CompletionStage<?> onBinary(WebSocket webSocket, ByteBuffer data, boolean last) {
        byte[] part = new byte[data.remaining()];
        data.get(part);
        binary.writeBytes(part);
        if (last) {
            byte[] whole = binary.toByteArray();
            binary.reset();
            if (whole.length == FoxgloveProtocol.TIME_BYTES && whole[0] == FoxgloveProtocol.TIME) {
                times.add(ByteBuffer.wrap(whole, 1, 8).order(ByteOrder.LITTLE_ENDIAN).getLong());
            } else {
                messages.add(whole);
            }
        }
        more(webSocket);
        return null;
    }

    @Override
    public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
        closeCode = statusCode;
        closed.countDown();
        return null;
    }

    private void more(WebSocket webSocket) {
        if (!paused) {
            webSocket.request(1);
        }
    }

    @Override
    public void close() {
        socket.abort();
    }
}
