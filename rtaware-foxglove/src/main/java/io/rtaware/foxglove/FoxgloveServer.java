package io.rtaware.foxglove;

import io.netty.bootstrap.ServerBootstrap;
import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFuture;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.channel.WriteBufferWaterMark;
import io.netty.channel.nio.NioIoHandler;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.handler.codec.http.FullHttpRequest;
import io.netty.handler.codec.http.HttpHeaderNames;
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
import java.net.Inet6Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Semaphore;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A Foxglove WebSocket server (as foxglove_bridge speaks it: subprotocol
 * {@value FoxgloveProtocol#SUBPROTOCOL_SDK} when the client offers it, else
 * {@value FoxgloveProtocol#SUBPROTOCOL}) fed by the recorder as its {@link RecordingTap}: every
 * channel of the recording is advertised with its ROS 2 type and {@code ros2msg} schema, and every
 * message the recorder's writer thread encodes is sent, as a Message Data frame stamped with its
 * log time, to each client subscribed to its channel. Latched channels ({@code /map},
 * {@code /tf_static}) give a new subscriber their last message, as a transient-local ROS 2 topic
 * does. With the {@value FoxgloveProtocol#CAPABILITY_TIME} capability it broadcasts the run's time
 * (the latest log time, at most every {@value #TIME_STEP_MS} ms of it) to every client, so
 * Foxglove's timeline follows world time at any time scale.
 *
 * <p>Bounded, so that no client can make the server hold more than it was told to:
 * <ul>
 *   <li>at most {@code maxClients} clients at once; a slot is taken when a client completes its
 *       WebSocket handshake, not when it connects, so idle connections cannot lock clients out.
 *       A client beyond the limit is closed after its handshake (close 1013, try again later) and
 *       counted ({@link FoxgloveStats#clientsRefused()});</li>
 *   <li>at most {@value #MAX_PENDING_HANDSHAKES} connections still in their handshake, each of
 *       which must finish it within {@value #HANDSHAKE_TIMEOUT_MS} ms of connecting (a trickle of
 *       bytes does not extend it); a new connection beyond that many closes the oldest pending
 *       one, so a flood of idle or slow connections delays a real client by at most one
 *       handshake;</li>
 *   <li>client messages of at most {@value #MAX_CLIENT_MESSAGE_BYTES} bytes (fragments
 *       included; a larger one closes that connection);</li>
 *   <li>per client at most {@code sendBufferBytes} waiting to be sent (Netty's write-buffer
 *       high-water mark), for every frame the server writes, data and control alike. A message
 *       that does not fit is not sent to that client and counted
 *       ({@link FoxgloveStats#messagesDropped()}); a status that does not fit likewise
 *       ({@link FoxgloveStats#statusesDropped()}); a client that cannot take its Server Info or an
 *       advertisement (it would miss channels for good) is closed and counted
 *       ({@link FoxgloveStats#clientsClosedSlow()}). While a client's buffer is full the server
 *       stops reading its requests, so a client that never reads cannot make it write more. A
 *       request's warnings of the same kind are one status ({@code no channel 5, 6, ...}).</li>
 * </ul>
 * So a slow client loses messages and never slows the writer thread, let alone a task (the task
 * threads never reach this class: the recorder's rings stand between). One event-loop thread
 * (Netty, daemon, {@code foxglove-server-*}) serves every connection.
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
    /** Connections that may be in their handshake at once; a new one beyond closes the oldest. */
    public static final int MAX_PENDING_HANDSHAKES = 32;
    /** Wall time a connection has, from when it is accepted, to finish the WebSocket handshake. */
    public static final long HANDSHAKE_TIMEOUT_MS = 10_000;
    /** Log time between two Time broadcasts, at least, ms. */
    public static final long TIME_STEP_MS = 50;
    /** Largest HTTP upgrade request read. */
    private static final int MAX_HANDSHAKE_BYTES = 16 << 10;
    /** Characters of a status message, at most (a longer one echoes a client's request and is cut). */
    private static final int MAX_STATUS_CHARS = 256;
    /** Ids a status names before it says how many more there are. */
    private static final int IDS_NAMED = 10;

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
    /** Connections accepted and still in their handshake, oldest first; the event-loop thread only. */
    private final ArrayDeque<Channel> pending = new ArrayDeque<>();

    private final AtomicLong accepted = new AtomicLong();
    private final AtomicLong refused = new AtomicLong();
    private final AtomicLong sent = new AtomicLong();
    private final AtomicLong sentBytes = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private final AtomicLong statusesDropped = new AtomicLong();
    private final AtomicLong closedSlow = new AtomicLong();
    private final AtomicLong closedInHandshake = new AtomicLong();
    private final AtomicLong requests = new AtomicLong();
    /** The log time last broadcast, ns; the writer thread only. */
    private long timeSentNs = Long.MIN_VALUE;
    private final AtomicBoolean closed = new AtomicBoolean();

    /** One advertised channel: its subscribers and, if latched, its last message. */
    private static final class Topic {
        final TapChannel channel;
        /**
         * Its subscribers, replaced (never changed in place) under this topic's lock, so that the
         * writer thread walks them by index with no iterator to allocate.
         */
        volatile Subscriber[] subscribers = NO_SUBSCRIBERS;
        /** The last message of a latched channel; guarded by this topic. */
        byte[] last = new byte[0];
        int lastLength = -1;
        long lastTimeNs;

        Topic(TapChannel channel) {
            this.channel = channel;
        }

        synchronized void add(Subscriber subscriber) {
            Subscriber[] more = Arrays.copyOf(subscribers, subscribers.length + 1);
            more[subscribers.length] = subscriber;
            subscribers = more;
        }

        synchronized void remove(Subscriber subscriber) {
            Subscriber[] now = subscribers;
            for (int i = 0; i < now.length; i++) {
                if (now[i] == subscriber) {
                    Subscriber[] fewer = Arrays.copyOf(now, now.length - 1);
                    System.arraycopy(now, i + 1, fewer, i, now.length - i - 1);
                    subscribers = fewer;
                    return;
                }
            }
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

    private static final Subscriber[] NO_SUBSCRIBERS = new Subscriber[0];

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
                .subprotocols(FoxgloveProtocol.SUBPROTOCOL_SDK + "," + FoxgloveProtocol.SUBPROTOCOL)
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
                        if (closed.get()) {
                            refused.incrementAndGet();
                            ch.close();
                            return;
                        }
                        admitPending(ch);
                        ch.pipeline().addLast(new HttpServerCodec(), new HttpObjectAggregator(MAX_HANDSHAKE_BYTES),
                                new PreferSdkSubprotocol(), new WebSocketServerProtocolHandler(websocket),
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
        InetAddress host = address.getAddress();
        String name = host.isAnyLocalAddress() && host instanceof Inet6Address ? "::" : host.getHostAddress();
        return new FoxgloveAddress(name, address.getPort()).toString();
    }

    /** @return the address listened on (the real port when 0 was asked for) */
    public InetSocketAddress address() {
        return bound;
    }

    /**
     * @return true if the server listens on more than this machine's loopback interface (every
     *     address, or an address other machines can reach): anyone who reaches it sees the run,
     *     since the protocol has no authentication
     */
    public boolean exposed() {
        return !bound.getAddress().isLoopbackAddress();
    }

    /**
     * @return where it listens, {@code HOST:PORT}, as bound: {@code 0.0.0.0:8765} or
     *     {@code [::]:8765} when it listens on every address
     */
    public String listening() {
        return describe(bound);
    }

    /**
     * @return the URL to open in Foxglove on this machine ("Open connection", "Foxglove
     *     WebSocket"): the loopback address when listening on every address (which
     *     {@link #listening} and {@link #exposed} say)
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

    /** @return client requests (text messages after the handshake) handled so far, by all clients */
    long requestsHandled() {
        return requests.get();
    }

    /**
     * @return the most bytes waiting to be sent to any one client now (Netty's outbound buffer,
     *     not the kernel's socket buffer)
     */
    long mostBytesWaiting() {
        long most = 0;
        for (Client c : clients) {
            Channel ch = c.channel;
            long waiting = ch.isWritable() ? sendBufferBytes - ch.bytesBeforeUnwritable()
                    : sendBufferBytes / 2 + ch.bytesBeforeWritable();
            most = Math.max(most, waiting);
        }
        return most;
    }

    /** @return what the server has done so far */
    public FoxgloveStats stats() {
        return new FoxgloveStats(describe(bound), maxClients, sendBufferBytes, accepted.get(), refused.get(),
                sent.get(), sentBytes.get(), dropped.get(), statusesDropped.get(), closedSlow.get(),
                closedInHandshake.get());
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
                sendRequired(c.channel, text);
            }
        }
    }

    @Override
    public void message(int channelId, long logTimeNs, byte[] data, int offset, int length) {
        if (logTimeNs - timeSentNs >= TIME_STEP_MS * 1_000_000L || timeSentNs == Long.MIN_VALUE) {
            broadcastTime(logTimeNs);
        }
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
        } else if (topic.subscribers.length > 0) {
            sendToSubscribers(topic, logTimeNs, data, offset, length);
        }
    }

    private void sendToSubscribers(Topic topic, long logTimeNs, byte[] data, int offset, int length) {
        Subscriber[] subscribers = topic.subscribers;
        for (int i = 0; i < subscribers.length; i++) {
            send(subscribers[i], logTimeNs, data, offset, length);
        }
    }

    /**
     * Sends every client a Time frame (the run's time moved on); a client with no room for it
     * misses this one, as it would a message.
     */
    private void broadcastTime(long logTimeNs) {
        timeSentNs = logTimeNs;
        for (Client c : clients) {
            Channel ch = c.channel;
            if (hasRoom(ch, FoxgloveProtocol.TIME_BYTES)) {
                ByteBuf frame = ch.alloc().buffer(FoxgloveProtocol.TIME_BYTES, FoxgloveProtocol.TIME_BYTES);
                FoxgloveProtocol.time(frame, logTimeNs);
                ch.writeAndFlush(new BinaryWebSocketFrame(frame), ch.voidPromise());
            }
        }
    }

    /** @return whether a connected client's send buffer has room for a frame of {@code bytes} */
    private static boolean hasRoom(Channel ch, int bytes) {
        return ch.isActive() && ch.bytesBeforeUnwritable() >= bytes;
    }

    /** Sends one Message Data frame, or drops and counts it if the client's send buffer has no room. */
    private void send(Subscriber subscriber, long logTimeNs, byte[] data, int offset, int length) {
        Channel ch = subscriber.client().channel;
        int frameBytes = FoxgloveProtocol.MESSAGE_DATA_HEADER_BYTES + length;
        if (!hasRoom(ch, frameBytes)) {
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

    /**
     * Puts {@value FoxgloveProtocol#SUBPROTOCOL_SDK} first among the subprotocols a client offers,
     * so that Netty's handshake (which takes the first offered that the server supports) selects
     * it whenever it is offered, whatever the client's order.
     */
    private static final class PreferSdkSubprotocol extends ChannelInboundHandlerAdapter {
        @Override
        public void channelRead(ChannelHandlerContext ctx, Object msg) throws Exception {
            if (msg instanceof FullHttpRequest request) {
                String offered = request.headers().get(HttpHeaderNames.SEC_WEBSOCKET_PROTOCOL);
                if (offered != null) {
                    List<String> names = new ArrayList<>();
                    for (String name : offered.split(",")) {
                        names.add(name.strip());
                    }
                    if (names.remove(FoxgloveProtocol.SUBPROTOCOL_SDK)) {
                        names.add(0, FoxgloveProtocol.SUBPROTOCOL_SDK);
                        request.headers().set(HttpHeaderNames.SEC_WEBSOCKET_PROTOCOL, String.join(",", names));
                    }
                }
            }
            ctx.fireChannelRead(msg);
        }
    }

    /** One connection's protocol handler, after Netty's WebSocket handshake handler. */
    private final class ClientHandler extends SimpleChannelInboundHandler<WebSocketFrame> {

        private Client client;

        @Override
        public void userEventTriggered(ChannelHandlerContext ctx, Object event) throws Exception {
            if (event instanceof WebSocketServerProtocolHandler.HandshakeComplete) {
                Channel ch = ctx.channel();
                pending.remove(ch);
                if (closed.get() || !slots.tryAcquire()) {
                    refused.incrementAndGet();
                    ch.writeAndFlush(new CloseWebSocketFrame(WebSocketCloseStatus.TRY_AGAIN_LATER,
                            "rtaware: " + maxClients + " clients are connected, the most it serves"))
                            .addListener(ChannelFutureListener.CLOSE);
                    return;
                }
                ch.closeFuture().addListener(f -> slots.release());
                client = new Client(ch);
                accepted.incrementAndGet();
                synchronized (advertising) {
                    clients.add(client);
                    if (sendRequired(ch, serverInfo)) {
                        sendRequired(ch, protocol.advertise(channels));
                    }
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
        public void channelWritabilityChanged(ChannelHandlerContext ctx) throws Exception {
            // A client whose buffer is full gets its requests read no further until it drains it:
            // what a request makes the server write stays within the bound.
            ctx.channel().config().setAutoRead(ctx.channel().isWritable());
            super.channelWritabilityChanged(ctx);
        }

        @Override
        public void channelInactive(ChannelHandlerContext ctx) throws Exception {
            if (client != null) {
                clients.remove(client);
                for (Subscriber s : client.subscriptions.values()) {
                    s.topic().remove(s);
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
        requests.incrementAndGet();
        FoxgloveProtocol.Request request;
        try {
            request = protocol.read(text);
        } catch (IllegalArgumentException e) {
            status(client, FoxgloveProtocol.STATUS_ERROR, "rtaware: " + e.getMessage());
            return;
        }
        if (request instanceof FoxgloveProtocol.Subscribe subscribe) {
            IdList unknown = new IdList();
            for (FoxgloveProtocol.Subscription s : subscribe.subscriptions()) {
                subscribe(client, s, unknown);
            }
            unknown.report(client, "no channel");
        } else if (request instanceof FoxgloveProtocol.Unsubscribe unsubscribe) {
            IdList unknown = new IdList();
            for (Long id : unsubscribe.subscriptionIds()) {
                Subscriber s = client.subscriptions.remove(id);
                if (s == null) {
                    unknown.add(id);
                } else {
                    s.topic().remove(s);
                }
            }
            unknown.report(client, "no subscription");
        } else if (request instanceof FoxgloveProtocol.Unsupported unsupported) {
            status(client, FoxgloveProtocol.STATUS_ERROR, "rtaware: '" + unsupported.op() + "' is not supported: this "
                    + "server only streams (no clientPublish, parameters, services or assets)");
        }
    }

    /** The ids one request named that the server does not know, told in one status. */
    private final class IdList {
        private final StringBuilder named = new StringBuilder();
        private int count;

        void add(long id) {
            if (count < IDS_NAMED) {
                named.append(count == 0 ? " " : ", ").append(id);
            }
            count++;
        }

        /** Sends one warning naming the first ids and how many there were; nothing if none. */
        void report(Client client, String what) {
            if (count > 0) {
                status(client, FoxgloveProtocol.STATUS_WARNING, "rtaware: " + what + named
                        + (count > IDS_NAMED ? " and " + (count - IDS_NAMED) + " more (" + count + " ids)" : ""));
            }
        }
    }

    private void subscribe(Client client, FoxgloveProtocol.Subscription request, IdList unknown) {
        Topic[] table = topics;
        Topic topic = request.channelId() < table.length ? table[(int) request.channelId()] : null;
        if (topic == null) {
            unknown.add(request.channelId());
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
                topic.add(subscriber);
            }
        } else {
            topic.add(subscriber);
        }
    }

    /**
     * Sends a status if the client's buffer has room for it; counts it as dropped if not. A
     * message echoing more than {@value #MAX_STATUS_CHARS} characters of a client's request is
     * cut there, so a status is never larger than the request's own words.
     */
    private void status(Client client, int level, String message) {
        String text = message.length() <= MAX_STATUS_CHARS ? message : message.substring(0, MAX_STATUS_CHARS) + "...";
        if (!offerText(client.channel, protocol.status(level, text))) {
            statusesDropped.incrementAndGet();
        }
    }

    /**
     * Sends what a client must get to follow the protocol (Server Info, an advertisement); a
     * client whose buffer has no room for it is closed and counted, since it would miss channels
     * for good.
     *
     * @return true if sent
     */
    private boolean sendRequired(Channel ch, String json) {
        if (offerText(ch, json)) {
            return true;
        }
        if (ch.isActive()) {
            closedSlow.incrementAndGet();
            ch.close();
        }
        return false;
    }

    /**
     * Writes a text frame if it fits in the client's send buffer: what waits to be sent to a
     * client stays under {@code sendBufferBytes}, except that a frame larger than the whole buffer
     * goes when nothing else waits (an advertisement of many channels to a small buffer).
     *
     * @return true if written
     */
    private boolean offerText(Channel ch, String json) {
        if (!ch.isActive()) {
            return false;
        }
        ByteBuf text = ByteBufUtil.writeUtf8(ch.alloc(), json);
        long room = ch.bytesBeforeUnwritable();
        if (text.readableBytes() > room && room < sendBufferBytes) {
            text.release();
            return false;
        }
        ch.writeAndFlush(new TextWebSocketFrame(text), ch.voidPromise());
        return true;
    }

    /**
     * Admits a new connection to its handshake: closes the oldest pending one if
     * {@value #MAX_PENDING_HANDSHAKES} are pending, and closes this one if its handshake is not
     * done {@value #HANDSHAKE_TIMEOUT_MS} ms after now. The event-loop thread only.
     */
    private void admitPending(Channel ch) {
        if (pending.size() >= MAX_PENDING_HANDSHAKES) {
            Channel oldest = pending.poll();
            closedInHandshake.incrementAndGet();
            oldest.close();
        }
        pending.add(ch);
        ScheduledFuture<?> deadline = ch.eventLoop().schedule(() -> {
            if (pending.remove(ch)) {
                closedInHandshake.incrementAndGet();
                ch.close();
            }
        }, HANDSHAKE_TIMEOUT_MS, TimeUnit.MILLISECONDS);
        ch.closeFuture().addListener(f -> {
            deadline.cancel(false);
            pending.remove(ch);
        });
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
