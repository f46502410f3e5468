package io.rtaware.foxglove;

import io.netty.bootstrap.ServerBootstrap;
import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFuture;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.channel.WriteBufferWaterMark;
import io.netty.channel.nio.NioIoHandler;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.handler.codec.http.HttpObjectAggregator;
import io.netty.handler.codec.http.HttpServerCodec;
import io.netty.handler.codec.http.websocketx.BinaryWebSocketFrame;
import io.netty.handler.codec.http.websocketx.CloseWebSocketFrame;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import io.netty.handler.codec.http.websocketx.WebSocketCloseStatus;
import io.netty.handler.codec.http.websocketx.WebSocketDecoderConfig;
import io.netty.handler.codec.http.websocketx.WebSocketFrame;
import io.netty.handler.codec.http.websocketx.WebSocketFrameAggregator;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolConfig;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolHandler;
import io.netty.util.concurrent.DefaultThreadFactory;
import io.rtaware.record.RecordingTap;
import io.rtaware.record.TapChannel;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A Foxglove WebSocket server (protocol v1, subprotocol {@value FoxgloveProtocol#SUBPROTOCOL}, as
 * foxglove_bridge speaks it) fed by the recorder as its {@link RecordingTap}: every channel of the
 * recording is advertised with its ROS 2 type and {@code ros2msg} schema, and every message the
 * recorder's writer thread encodes is sent, as a Message Data frame stamped with its log time,
 * to each client subscribed to its channel. Latched channels ({@code /map}, {@code /tf_static})
 * give a new subscriber their last message, as a transient-local ROS 2 topic does.
 *
 * <p>Bounded: at most {@code maxClients} clients at once (more are refused when they connect,
 * and counted), client messages of at most {@value #MAX_CLIENT_MESSAGE_BYTES} bytes (fragments
 * included; a larger one closes that connection), and per
 * client at most {@code sendBufferBytes} waiting to be sent (Netty's write-buffer high-water
 * mark): a message that does not fit is not sent to that client and is counted
 * ({@link FoxgloveStats#messagesDropped()}), so a slow client loses messages and never slows the
 * writer thread, let alone a task (the task threads never reach this class: the recorder's rings
 * stand between). One event-loop thread (Netty, daemon, {@code foxglove-server-*}) serves every connection.
 *
 * <p>Thread-safe: {@link #channel} from any thread, {@link #message} from one thread at a time
 * (the recorder's writer thread), {@link #stats} and {@link #close} from any thread.
 */
public final class FoxgloveServer implements RecordingTap, AutoCloseable {

    /** Clients served at once by default. */
    public static final int DEFAULT_MAX_CLIENTS = 8;
    /** Bytes each client may have waiting by default (foxglove_bridge's default limit is 10 MB). */
    public static final int DEFAULT_SEND_BUFFER_BYTES = 8 << 20;
    /** Largest message a client may send (a subscribe of every channel is far smaller). */
    public static final int MAX_CLIENT_MESSAGE_BYTES = 64 << 10;
    /** Largest HTTP upgrade request read. */
    private static final int MAX_HANDSHAKE_BYTES = 16 << 10;
    /** Wall time a connection has to finish the WebSocket handshake. */
    private static final long HANDSHAKE_TIMEOUT_MS = 10_000;

    private final FoxgloveProtocol protocol = new FoxgloveProtocol();
    private final int maxClients;
    private final int sendBufferBytes;
    private final Semaphore slots;
    private final String serverInfo;
    private final EventLoopGroup group;
    private final Channel server;
    private final InetSocketAddress bound;

    /** Guards the channel list and the topic table's growth, and orders advertisements. */
    private final Object advertising = new Object();
    private final List<TapChannel> channels = new ArrayList<>();
    /** Topics by channel id; replaced (never changed in place) under {@link #advertising}. */
    private volatile Topic[] topics = new Topic[1];
    private final Set<Client> clients = ConcurrentHashMap.newKeySet();

    private final AtomicLong accepted = new AtomicLong();
    private final AtomicLong refused = new AtomicLong();
    private final AtomicLong sent = new AtomicLong();
    private final AtomicLong sentBytes = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private final AtomicBoolean closed = new AtomicBoolean();

    /** One advertised channel: its subscribers and, if latched, its last message. */
    private static final class Topic {
        final TapChannel channel;
        final CopyOnWriteArrayList<Subscriber> subscribers = new CopyOnWriteArrayList<>();
        /** The last message of a latched channel; guarded by this topic. */
        byte[] last = new byte[0];
        int lastLength = -1;
        long lastTimeNs;

        Topic(TapChannel channel) {
            this.channel = channel;
        }

        /** Keeps a latched channel's message for later subscribers (grows its buffer when needed). */
        void keep(long timeNs, byte[] data, int offset, int length) {
            if (last.length < length) {
                last = new byte[length];
            }
            System.arraycopy(data, offset, last, 0, length);
            lastLength = length;
            lastTimeNs = timeNs;
        }
    }

    /** One subscription of one client. */
    private record Subscriber(Client client, int id, Topic topic) {
    }

    /** One connected client (after its handshake). */
    private static final class Client {
        final Channel channel;
        /** Its subscriptions by id; the event-loop thread only. */
        final Map<Long, Subscriber> subscriptions = new HashMap<>();

        Client(Channel channel) {
            this.channel = channel;
        }
    }

    private FoxgloveServer(InetSocketAddress address, String name, Map<String, String> metadata, int maxClients,
                           int sendBufferBytes) {
        this.maxClients = maxClients;
        this.sendBufferBytes = sendBufferBytes;
        this.slots = new Semaphore(maxClients);
        this.serverInfo = protocol.serverInfo(name, Long.toString(System.currentTimeMillis()), metadata);
        WebSocketServerProtocolConfig websocket = WebSocketServerProtocolConfig.newBuilder()
                .websocketPath("/")
                .checkStartsWith(true)
                .subprotocols(FoxgloveProtocol.SUBPROTOCOL)
                .handshakeTimeoutMillis(HANDSHAKE_TIMEOUT_MS)
                .decoderConfig(WebSocketDecoderConfig.newBuilder().maxFramePayloadLength(MAX_CLIENT_MESSAGE_BYTES)
                        .allowExtensions(false).build())
                .build();
        // Not named rtaware-*: bench's allocation check counts those threads as the framework's.
        group = new MultiThreadIoEventLoopGroup(1, new DefaultThreadFactory("foxglove-server", true),
                NioIoHandler.newFactory());
        ServerBootstrap bootstrap = new ServerBootstrap()
                .group(group)
                .channel(NioServerSocketChannel.class)
                .childOption(ChannelOption.TCP_NODELAY, true)
                .childOption(ChannelOption.WRITE_BUFFER_WATER_MARK,
                        new WriteBufferWaterMark(sendBufferBytes / 2, sendBufferBytes))
                .childHandler(new ChannelInitializer<SocketChannel>() {
                    @Override
                    protected void initChannel(SocketChannel ch) {
                        if (closed.get() || !slots.tryAcquire()) {
                            refused.incrementAndGet();
                            ch.close();
                            return;
                        }
                        ch.closeFuture().addListener(f -> slots.release());
                        ch.pipeline().addLast(new HttpServerCodec(), new HttpObjectAggregator(MAX_HANDSHAKE_BYTES),
                                new WebSocketServerProtocolHandler(websocket),
                                new WebSocketFrameAggregator(MAX_CLIENT_MESSAGE_BYTES), new ClientHandler());
                    }
                });
        ChannelFuture bind = bootstrap.bind(address).awaitUninterruptibly();
        if (!bind.isSuccess()) {
            group.shutdownGracefully(0, 0, TimeUnit.MILLISECONDS).awaitUninterruptibly();
            Throwable cause = bind.cause();
            throw new FoxgloveAddressException("cannot serve Foxglove on " + describe(address) + ": "
                    + (cause.getMessage() == null ? cause.toString() : cause.getMessage())
                    + " (the port is in use, or the host is not an address of this machine)");
        }
        server = bind.channel();
        bound = (InetSocketAddress) server.localAddress();
    }

    /**
     * Starts serving as {@code --foxglove} does, from a program's own {@code main}: at most
     * {@value #DEFAULT_MAX_CLIENTS} clients, {@value #DEFAULT_SEND_BUFFER_BYTES} bytes waiting per
     * client, and the {@code ROS_DISTRO} of the recordings ({@link TapChannel#ROS_DISTRO}) in the
     * Server Info. Feed it by naming it as the {@code tap} of a recording's plan; close it once the
     * recorder has finished.
     *
     * @param address where to listen ({@code FoxgloveAddress.parse("8765")}: port 8765 of
     *     127.0.0.1; port 0 for a free one)
     * @param name the server's name in its Server Info (Foxglove shows it)
     * @return the server, listening
     * @throws FoxgloveAddressException if the host does not resolve or the address cannot be bound
     */
    public static FoxgloveServer start(FoxgloveAddress address, String name) {
        return start(address, name, Map.of("ROS_DISTRO", TapChannel.ROS_DISTRO), DEFAULT_MAX_CLIENTS,
                DEFAULT_SEND_BUFFER_BYTES);
    }

    /**
     * Starts serving.
     *
     * @param address where to listen (port 0 for a free one)
     * @param name the server's name in its Server Info
     * @param metadata the Server Info's metadata (e.g. {@code ROS_DISTRO})
     * @param maxClients clients served at once, at least 1
     * @param sendBufferBytes bytes each client may have waiting to be sent, at least 1024
     * @return the server, listening
     * @throws FoxgloveAddressException if the host does not resolve or the address cannot be bound
     */
    public static FoxgloveServer start(FoxgloveAddress address, String name, Map<String, String> metadata,
                                       int maxClients, int sendBufferBytes) {
        if (maxClients < 1) {
            throw new IllegalArgumentException("maxClients must be at least 1, got " + maxClients);
        }
        if (sendBufferBytes < 1024) {
            throw new IllegalArgumentException("sendBufferBytes must be at least 1024, got " + sendBufferBytes);
        }
        InetAddress host;
        try {
            host = InetAddress.getByName(address.host());
        } catch (UnknownHostException e) {
            throw new FoxgloveAddressException("cannot resolve '" + address.host() + "' to an address of this machine");
        }
        return new FoxgloveServer(new InetSocketAddress(host, address.port()), name, Map.copyOf(metadata), maxClients,
                sendBufferBytes);
    }

    private static String describe(InetSocketAddress address) {
        return new FoxgloveAddress(address.getAddress().getHostAddress(), address.getPort()).toString();
    }

    /** @return the address listened on (the real port when 0 was asked for) */
    public InetSocketAddress address() {
        return bound;
    }

    /**
     * @return the URL to open in Foxglove ("Open connection", "Foxglove WebSocket"): the
     *     loopback address when listening on every address
     */
    public String url() {
        InetAddress host = bound.getAddress();
        String name = host.isAnyLocalAddress() ? FoxgloveAddress.LOOPBACK : host.getHostAddress();
        return "ws://" + new FoxgloveAddress(name, bound.getPort());
    }

    /** @return clients connected now (their handshake done) */
    public int clients() {
        return clients.size();
    }

    /** @return what the server has done so far */
    public FoxgloveStats stats() {
        return new FoxgloveStats(describe(bound), maxClients, sendBufferBytes, accepted.get(), refused.get(),
                sent.get(), sentBytes.get(), dropped.get());
    }

    // ---------------------------------------------------------------- the recorder's side

    @Override
    public void channel(TapChannel channel) {
        if (channel.id() < 1) {
            throw new IllegalArgumentException("channel ids start at 1, got " + channel.id());
        }
        synchronized (advertising) {
            Topic[] table = Arrays.copyOf(topics, Math.max(topics.length, channel.id() + 1));
            table[channel.id()] = new Topic(channel);
            topics = table;
            channels.add(channel);
            String text = protocol.advertise(List.of(channel));
            for (Client c : clients) {
                c.channel.writeAndFlush(new TextWebSocketFrame(text));
            }
        }
    }

    @Override
    public void message(int channelId, long logTimeNs, byte[] data, int offset, int length) {
        Topic[] table = topics;
        Topic topic = channelId > 0 && channelId < table.length ? table[channelId] : null;
        if (topic == null) {
            return;
        }
        if (topic.channel.latched()) {
            synchronized (topic) {
                topic.keep(logTimeNs, data, offset, length);
                sendToSubscribers(topic, logTimeNs, data, offset, length);
            }
        } else if (!topic.subscribers.isEmpty()) {
            sendToSubscribers(topic, logTimeNs, data, offset, length);
        }
    }

    private void sendToSubscribers(Topic topic, long logTimeNs, byte[] data, int offset, int length) {
        for (Subscriber s : topic.subscribers) {
            send(s, logTimeNs, data, offset, length);
        }
    }

    /** Sends one Message Data frame, or drops and counts it if the client's send buffer has no room. */
    private void send(Subscriber subscriber, long logTimeNs, byte[] data, int offset, int length) {
        Channel ch = subscriber.client().channel;
        int frameBytes = FoxgloveProtocol.MESSAGE_DATA_HEADER_BYTES + length;
        if (!ch.isActive() || ch.bytesBeforeUnwritable() < frameBytes) {
            dropped.incrementAndGet();
            return;
        }
        ByteBuf frame = ch.alloc().buffer(frameBytes, frameBytes);
        FoxgloveProtocol.messageDataHeader(frame, subscriber.id(), logTimeNs);
        frame.writeBytes(data, offset, length);
        ch.writeAndFlush(new BinaryWebSocketFrame(frame), ch.voidPromise());
        sent.incrementAndGet();
        sentBytes.addAndGet(frameBytes);
    }

    // ---------------------------------------------------------------- the clients' side (event loop)

    /** One connection's protocol handler, after Netty's WebSocket handshake handler. */
    private final class ClientHandler extends SimpleChannelInboundHandler<WebSocketFrame> {

        private Client client;

        @Override
        public void userEventTriggered(ChannelHandlerContext ctx, Object event) throws Exception {
            if (event instanceof WebSocketServerProtocolHandler.HandshakeComplete) {
                client = new Client(ctx.channel());
                accepted.incrementAndGet();
                synchronized (advertising) {
                    clients.add(client);
                    ctx.write(new TextWebSocketFrame(serverInfo));
                    ctx.writeAndFlush(new TextWebSocketFrame(protocol.advertise(channels)));
                }
                return;
            }
            super.userEventTriggered(ctx, event);
        }

        @Override
        protected void channelRead0(ChannelHandlerContext ctx, WebSocketFrame frame) {
            if (client == null) {
                return;
            }
            if (frame instanceof TextWebSocketFrame text) {
                handle(client, text.text());
            } else {
                status(client, FoxgloveProtocol.STATUS_ERROR, "binary client messages are not supported: this "
                        + "server only streams (no clientPublish, services or assets)");
            }
        }

        @Override
        public void channelInactive(ChannelHandlerContext ctx) throws Exception {
            if (client != null) {
                clients.remove(client);
                for (Subscriber s : client.subscriptions.values()) {
                    s.topic().subscribers.remove(s);
                }
                client.subscriptions.clear();
            }
            super.channelInactive(ctx);
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            ctx.close(); // a broken connection or a protocol violation ends that client only
        }
    }

    private void handle(Client client, String text) {
        FoxgloveProtocol.Request request;
        try {
            request = protocol.read(text);
        } catch (IllegalArgumentException e) {
            status(client, FoxgloveProtocol.STATUS_ERROR, "rtaware: " + e.getMessage());
            return;
        }
        if (request instanceof FoxgloveProtocol.Subscribe subscribe) {
            for (FoxgloveProtocol.Subscription s : subscribe.subscriptions()) {
                subscribe(client, s);
            }
        } else if (request instanceof FoxgloveProtocol.Unsubscribe unsubscribe) {
            for (Long id : unsubscribe.subscriptionIds()) {
                Subscriber s = client.subscriptions.remove(id);
                if (s == null) {
                    status(client, FoxgloveProtocol.STATUS_WARNING, "rtaware: no subscription " + id);
                } else {
                    s.topic().subscribers.remove(s);
                }
            }
        } else if (request instanceof FoxgloveProtocol.Unsupported unsupported) {
            status(client, FoxgloveProtocol.STATUS_ERROR, "rtaware: '" + unsupported.op() + "' is not supported: this "
                    + "server only streams (no clientPublish, parameters, services or assets)");
        }
    }

    private void subscribe(Client client, FoxgloveProtocol.Subscription request) {
        Topic[] table = topics;
        Topic topic = request.channelId() < table.length ? table[(int) request.channelId()] : null;
        if (topic == null) {
            status(client, FoxgloveProtocol.STATUS_WARNING, "rtaware: no channel " + request.channelId());
            return;
        }
        if (client.subscriptions.containsKey(request.id())) {
            status(client, FoxgloveProtocol.STATUS_ERROR, "rtaware: subscription id " + request.id() + " is in use");
            return;
        }
        for (Subscriber s : client.subscriptions.values()) {
            if (s.topic() == topic) {
                status(client, FoxgloveProtocol.STATUS_WARNING, "rtaware: channel " + request.channelId() + " ("
                        + topic.channel.topic() + ") is subscribed already, as subscription " + s.id());
                return;
            }
        }
        Subscriber subscriber = new Subscriber(client, (int) request.id(), topic);
        client.subscriptions.put(request.id(), subscriber);
        if (topic.channel.latched()) {
            synchronized (topic) {
                if (topic.lastLength >= 0) {
                    send(subscriber, topic.lastTimeNs, topic.last, 0, topic.lastLength);
                }
                topic.subscribers.add(subscriber);
            }
        } else {
            topic.subscribers.add(subscriber);
        }
    }

    private void status(Client client, int level, String message) {
        client.channel.writeAndFlush(new TextWebSocketFrame(protocol.status(level, message)));
    }

    /**
     * Stops listening, closes every client's connection (WebSocket close 1001, after what was
     * already queued for it) and stops the event loop. Idempotent.
     */
    @Override
    public void close() {
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        for (Client c : clients) {
            c.channel.writeAndFlush(new CloseWebSocketFrame(WebSocketCloseStatus.ENDPOINT_UNAVAILABLE, "rtaware stopped"))
                    .addListener(ChannelFutureListener.CLOSE);
        }
        server.close().awaitUninterruptibly();
        group.shutdownGracefully(100, 2_000, TimeUnit.MILLISECONDS).awaitUninterruptibly();
    }
}
