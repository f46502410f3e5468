package io.rtaware.ros2.graph;

import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohSession;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;

/**
 * One Zenoh session in the role of an rmw_zenoh context: a ROS domain, the ROS 2 distribution
 * whose rmw_zenoh conventions it follows, and the counter from which node and entity ids are
 * drawn (decimal, from 0). Thread-safe; closing it closes the session and with it every node's
 * tokens, publishers and subscribers.
 */
public final class Ros2Context implements AutoCloseable {

    private final ZenohSession session;
    private final int domain;
    private final Ros2Distro distro;
    private final AtomicLong nextId = new AtomicLong();

    /**
     * @param session an open session, owned by the context from now on
     * @param domain the ROS domain id (0..232 as in ROS 2)
     * @param distro the distribution whose rmw_zenoh conventions to follow
     */
    public Ros2Context(ZenohSession session, int domain, Ros2Distro distro) {
        this.session = Objects.requireNonNull(session, "session");
        this.domain = checkDomain(domain);
        this.distro = Objects.requireNonNull(distro, "distro");
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

    /** Closes the session, and with it everything declared in it. */
    @Override
    public void close() throws ZenohException {
        session.close();
    }
}
