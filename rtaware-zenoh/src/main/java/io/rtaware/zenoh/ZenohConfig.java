package io.rtaware.zenoh;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * How a {@link ZenohSession} is opened, validated once on construction. Immutable and
 * thread-safe. Only TCP endpoints are accepted (the native layer is built with Zenoh's TCP
 * transport only).
 *
 * @param mode peer (talks to peers and routers) or client (talks through one router)
 * @param connect endpoints to connect to, such as {@code tcp/127.0.0.1:7447}; when not empty,
 *     opening fails if none is reachable within {@code connectTimeoutMs}
 * @param listen endpoints to listen on ({@code tcp/127.0.0.1:0} picks a free loopback port)
 * @param multicastScouting whether to discover peers by UDP multicast
 * @param connectTimeoutMs how long opening waits for the connect endpoints
 */
public record ZenohConfig(Mode mode, List<String> connect, List<String> listen, boolean multicastScouting,
                          long connectTimeoutMs) {

    /** Zenoh's session modes that rtaware uses. */
    public enum Mode {
        /** a peer: connects to routers and peers, accepts connections on its listen endpoints */
        PEER,
        /** a client: everything goes through the router it connects to */
        CLIENT
    }

    /** The loopback endpoint on a free port: where a session listens unless told otherwise. */
    public static final String LOOPBACK_ANY_PORT = "tcp/127.0.0.1:0";

    private static final Pattern TCP_ENDPOINT = Pattern.compile("tcp/(\\[[0-9A-Fa-f:.]+]|[A-Za-z0-9.-]+):(\\d{1,5})");

    /**
     * @param mode peer or client
     * @param connect endpoints to connect to (TCP only)
     * @param listen endpoints to listen on (TCP only)
     * @param multicastScouting whether to discover peers by UDP multicast
     * @param connectTimeoutMs how long opening waits for the connect endpoints, positive
     * @throws IllegalArgumentException naming the first invalid field and its value
     */
    public ZenohConfig {
        if (mode == null) {
            throw new IllegalArgumentException("Zenoh mode is missing");
        }
        connect = List.copyOf(connect);
        listen = List.copyOf(listen);
        for (String endpoint : connect) {
            checkEndpoint(endpoint, false);
        }
        for (String endpoint : listen) {
            checkEndpoint(endpoint, true);
        }
        if (mode == Mode.CLIENT && connect.isEmpty()) {
            throw new IllegalArgumentException("a Zenoh client needs at least one connect endpoint");
        }
        if (connectTimeoutMs <= 0) {
            throw new IllegalArgumentException("Zenoh connect timeout must be positive: " + connectTimeoutMs + " ms");
        }
    }

    /**
     * A peer that listens on a free loopback port, connects nowhere, and does not scout:
     * the rmw_zenoh defaults without the router.
     *
     * @return the configuration
     */
    public static ZenohConfig loopbackPeer() {
        return new ZenohConfig(Mode.PEER, List.of(), List.of(LOOPBACK_ANY_PORT), false, 3000);
    }

    /**
     * @param endpoints where to connect
     * @return a copy connecting there
     */
    public ZenohConfig withConnect(List<String> endpoints) {
        return new ZenohConfig(mode, endpoints, listen, multicastScouting, connectTimeoutMs);
    }

    /**
     * @param endpoints where to listen
     * @return a copy listening there
     */
    public ZenohConfig withListen(List<String> endpoints) {
        return new ZenohConfig(mode, connect, endpoints, multicastScouting, connectTimeoutMs);
    }

    /**
     * Checks that an endpoint is {@code tcp/HOST:PORT}.
     *
     * @param endpoint the text
     * @param listen whether port 0 (a free port) is allowed
     * @return the endpoint
     * @throws IllegalArgumentException naming the endpoint and what is wrong
     */
    public static String checkEndpoint(String endpoint, boolean listen) {
        Matcher m = TCP_ENDPOINT.matcher(endpoint == null ? "" : endpoint);
        if (!m.matches()) {
            throw new IllegalArgumentException("malformed Zenoh endpoint '" + endpoint + "' (expected tcp/HOST:PORT)");
        }
        int port = Integer.parseInt(m.group(2));
        if (port > 65535 || (port == 0 && !listen)) {
            throw new IllegalArgumentException("malformed Zenoh endpoint '" + endpoint + "' (port "
                    + port + " outside " + (listen ? "0" : "1") + "..65535)");
        }
        return endpoint;
    }
}
