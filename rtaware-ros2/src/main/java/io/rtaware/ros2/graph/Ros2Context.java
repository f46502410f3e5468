package io.rtaware.ros2.graph;

import io.rtaware.zenoh.DdsBridge;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohSession;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * One Zenoh session in the role of an rmw_zenoh context: a ROS domain, the ROS 2 distribution
 * whose rmw_zenoh conventions it follows, and the counter from which node and entity ids are
 * drawn (decimal, from 0). Thread-safe; closing it closes the session and with it every node's
 * tokens, publishers and subscribers.
 *
 * <p>With {@link Ros2Transport#DDS} ({@link #openDds}) the session is connected to a ROS 2 DDS
 * bridge of its own (a process this one starts), which the context owns and closes: topics are the bridge's
 * keys and routes are announced to it ({@link Ros2Node}).
 */
public final class Ros2Context implements AutoCloseable {

    /** The most publishers of one topic {@link #publishedTypes} reads. */
    public static final int MAX_GRAPH_REPLIES = 1_000;
    /** The largest description of one DDS writer the bridge's admin space may answer (a little JSON). */
    private static final int MAX_GRAPH_REPLY_BYTES = 64 * 1024;
    /** How long {@link #publishedTypes} waits for the graph's answers. */
    private static final long GRAPH_QUERY_TIMEOUT_MS = 500;
    /** The type name in the plugin's JSON description of a DDS writer. */
    private static final Pattern DDS_TYPE_NAME = Pattern.compile("\"type_name\"\\s*:\\s*\"([^\"]*)\"");
    /** Where an rmw_zenoh entity token names its type: after the domain, ids, kind, node and topic. */
    private static final int TOKEN_TYPE_SEGMENT = 10;

    private final ZenohSession session;
    private final int domain;
    private final Ros2Distro distro;
    private final Ros2Transport transport;
    private final DdsBridge bridge;
    private final AtomicLong nextId = new AtomicLong();

    /**
     * @param session an open session, owned by the context from now on
     * @param domain the ROS domain id (0..232 as in ROS 2)
     * @param distro the distribution whose rmw_zenoh conventions to follow
     */
    public Ros2Context(ZenohSession session, int domain, Ros2Distro distro) {
        this(session, domain, distro, Ros2Transport.RMW_ZENOH, null);
    }

    private Ros2Context(ZenohSession session, int domain, Ros2Distro distro, Ros2Transport transport, DdsBridge bridge) {
        this.session = Objects.requireNonNull(session, "session");
        this.domain = checkDomain(domain);
        this.distro = Objects.requireNonNull(distro, "distro");
        this.transport = transport;
        this.bridge = bridge;
    }

    /**
     * Starts a ROS 2 DDS bridge on {@code settings}' domain and opens a session connected to it
     * (and to nothing else). Returns once the bridge's plugin has announced itself, so that routes
     * declared next reach DDS.
     *
     * @param settings the DDS domain and reach
     * @param startTimeoutMs how long to wait for the bridge to start, and again for its plugin to
     *     announce itself
     * @return a context on DDS
     * @throws ZenohException if the bridge is not in this build, or it or the session cannot start
     */
    public static Ros2Context openDds(DdsSettings settings, long startTimeoutMs) throws ZenohException {
        DdsBridge bridge = DdsBridge.start(settings.bridgeConfig(ZenohConfig.LOOPBACK_ANY_PORT), startTimeoutMs);
        ZenohSession session = null;
        try {
            session = ZenohSession.open(ZenohConfig.loopbackPeer().withListen(List.of()).withConnect(List.of(bridge.endpoint())));
            awaitPlugin(session, bridge.zid(), startTimeoutMs);
            return new Ros2Context(session, settings.domain(), settings.distro(), Ros2Transport.DDS, bridge);
        } catch (ZenohException | RuntimeException e) {
            try {
                if (session != null) {
                    session.close();
                }
            } finally {
                bridge.close();
            }
            throw e;
        }
    }

    /** Waits until the plugin's liveliness token ({@code @/<zid>/@ros2_lv}) is seen. */
    private static void awaitPlugin(ZenohSession session, String bridgeZid, long timeoutMs) throws ZenohException {
        String token = "@/" + bridgeZid + "/@ros2_lv";
        long deadlineNs = System.nanoTime() + timeoutMs * 1_000_000L;
        while (!session.livelinessKeys(token, 200).contains(token)) {
            if (System.nanoTime() - deadlineNs > 0) {
                throw new ZenohException("the ROS 2 DDS bridge did not start within " + timeoutMs
                        + " ms (its plugin logs why on stderr with RUST_LOG=zenoh_plugin_ros2dds=debug)");
            }
        }
    }

    /**
     * The message types the ROS graph shows the publishers of a topic with, as ROS 2 names them
     * ({@code sensor_msgs/msg/LaserScan}). Over DDS, every DDS writer on the topic's DDS name
     * ({@code rt/scan}) that the bridge discovered through Cyclone DDS's {@code DCPSPublication}
     * built-in topic, a ROS 2 node's or not: its plugin lists them in its admin space,
     * {@code @/<zid>/ros2/dds/<participant>/writer/<writer>/<topic>}, with their type names. Over
     * rmw_zenoh, the publishers' liveliness tokens on the context's domain. At most
     * {@value #MAX_GRAPH_REPLIES} publishers are read.
     *
     * @param fullTopic a fully qualified topic name
     * @return the distinct types, in the order first seen; empty when nobody publishes the topic
     * @throws ZenohException if the session is closed or the graph answers beyond its bounds
     */
    public Set<String> publishedTypes(String fullTopic) throws ZenohException {
        Set<String> types = new LinkedHashSet<>();
        if (transport == Ros2Transport.DDS) {
            String selector = "@/" + bridge.zid() + "/ros2/dds/*/writer/*/" + ddsTopic(fullTopic);
            for (ZenohSession.Reply reply : session.get(selector, GRAPH_QUERY_TIMEOUT_MS, MAX_GRAPH_REPLIES,
                    MAX_GRAPH_REPLY_BYTES)) {
                Matcher type = DDS_TYPE_NAME.matcher(reply.text());
                if (type.find()) {
                    types.add(Ros2Names.rosTypeName(type.group(1)));
                }
            }
        } else {
            String pattern = "@ros2_lv/" + domain + "/*/*/*/MP/*/*/*/" + Ros2Names.mangle(fullTopic) + "/*/*/*";
            for (String token : session.livelinessKeys(pattern, GRAPH_QUERY_TIMEOUT_MS, MAX_GRAPH_REPLIES)) {
                String[] segments = token.split("/");
                if (segments.length > TOKEN_TYPE_SEGMENT) {
                    types.add(Ros2Names.rosTypeName(segments[TOKEN_TYPE_SEGMENT]));
                }
            }
        }
        return types;
    }

    /**
     * @param fullTopic a fully qualified topic name
     * @return how the topic is named on this context's wire: {@code rt/scan} on DDS, {@code /scan}
     *     on rmw_zenoh
     */
    public String wireName(String fullTopic) {
        return transport == Ros2Transport.DDS ? ddsTopic(fullTopic) : fullTopic;
    }

    private static String ddsTopic(String fullTopic) {
        return "rt" + fullTopic;
    }

    /**
     * A context in the conventions of {@link Ros2Distro#newest()}.
     *
     * @param config how to open the session
     * @param domain the ROS domain id
     * @return a context on a new session
     * @throws ZenohException if the session cannot be opened
     */
    public static Ros2Context open(ZenohConfig config, int domain) throws ZenohException {
        return open(config, domain, Ros2Distro.newest());
    }

    /**
     * @param config how to open the session
     * @param domain the ROS domain id
     * @param distro the distribution whose rmw_zenoh conventions to follow
     * @return a context on a new session
     * @throws ZenohException if the session cannot be opened
     */
    public static Ros2Context open(ZenohConfig config, int domain, Ros2Distro distro) throws ZenohException {
        checkDomain(domain);
        Objects.requireNonNull(distro, "distro");
        return new Ros2Context(ZenohSession.open(config), domain, distro);
    }

    /**
     * @param domain a domain id
     * @return it
     * @throws IllegalArgumentException outside 0..232
     */
    public static int checkDomain(int domain) {
        if (domain < 0 || domain > 232) {
            throw new IllegalArgumentException("ROS domain id must be 0..232, got " + domain);
        }
        return domain;
    }

    /**
     * Creates a node and declares its liveliness token.
     *
     * @param namespace the node's namespace ({@code /} for none)
     * @param name the node's name
     * @return the node
     * @throws ZenohException if the token cannot be declared
     */
    public Ros2Node createNode(String namespace, String name) throws ZenohException {
        return new Ros2Node(this, Ros2Names.namespace(namespace), Ros2Names.nodeName(name), nextId());
    }

    long nextId() {
        return nextId.getAndIncrement();
    }

    /** @return the session */
    public ZenohSession session() {
        return session;
    }

    /** @return the ROS domain id */
    public int domain() {
        return domain;
    }

    /** @return the distribution whose rmw_zenoh conventions this context follows */
    public Ros2Distro distro() {
        return distro;
    }

    /** @return how this context reaches the ROS graph */
    public Ros2Transport transport() {
        return transport;
    }

    /** Closes the session, and with it everything declared in it, then the DDS bridge if any. */
    @Override
    public void close() throws ZenohException {
        try {
            session.close();
        } finally {
            if (bridge != null) {
                bridge.close();
            }
        }
    }
}
