package io.rtaware.ros2.graph;

import io.rtaware.ros2msg.Ros2MessageType;
import io.rtaware.zenoh.LivelinessToken;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohMailbox;
import io.rtaware.zenoh.ZenohPublisher;

/**
 * A ROS 2 node: its liveliness token, and the publishers and subscriptions it declares, each
 * with its own entity token so that the ROS graph lists them. Thread-safe.
 */
public final class Ros2Node {

    /** Token kinds of rmw_zenoh. */
    private static final String NODE = "NN";
    private static final String PUBLISHER = "MP";
    private static final String SUBSCRIPTION = "MS";
    /** The enclave of every rtaware node: none, written as an empty name. */
    private static final String ENCLAVE = "";

    private final Ros2Context context;
    private final String namespace;
    private final String name;
    private final long nodeId;

    Ros2Node(Ros2Context context, String namespace, String name, long nodeId) throws ZenohException {
        this.context = context;
        this.namespace = namespace;
        this.name = name;
        this.nodeId = nodeId;
        if (dds()) {
            return; // on DDS the bridge is the node the graph sees (BRIDGE_NODE)
        }
        context.session().declareToken(nodeToken());
    }

    private boolean dds() {
        return context.transport() == Ros2Transport.DDS;
    }

    /**
     * The node's liveliness key:
     * {@code @ros2_lv/<domain>/<zid>/<node id>/<node id>/NN/<enclave>/<namespace>/<name>}.
     *
     * @return the key
     */
    public String nodeToken() {
        return prefix(nodeId, NODE);
    }

    private String prefix(long entityId, String kind) {
        return "@ros2_lv/" + context.domain() + "/" + context.session().zid() + "/" + nodeId + "/" + entityId + "/"
                + kind + "/" + Ros2Names.mangle(ENCLAVE) + "/" + Ros2Names.mangle(namespace) + "/" + name;
    }

    /**
     * An entity's liveliness key: the node's fields, then
     * {@code /<topic>/<dds type>/<type hash>/<qos>}.
     *
     * @param entityId the entity's id
     * @param kind MP or MS
     * @param fullTopic the fully qualified topic
     * @param type the message type
     * @param qos the QoS profile
     * @return the key
     */
    String entityToken(long entityId, String kind, String fullTopic, Ros2MessageType type, QosProfile qos) {
        return prefix(entityId, kind) + "/" + Ros2Names.mangle(fullTopic) + "/" + type.ddsTypeName() + "/"
                + context.distro().typeHash(type) + "/" + qos.tokenText();
    }

    /**
     * @param fullTopic a fully qualified topic name
     * @param type its message type
     * @return the topic's key expression in the context's distribution
     */
    String topicKey(String fullTopic, Ros2MessageType type) {
        return dds() ? Ros2Names.bridgeKey(fullTopic)
                : Ros2Names.topicKey(context.domain(), fullTopic, type.ddsTypeName(), context.distro().typeHash(type));
    }

    private String bridgeAnnouncement(String kind, String fullTopic, Ros2MessageType type, QosProfile qos) {
        String typeHash = context.distro() == Ros2Distro.HUMBLE ? null : context.distro().typeHash(type);
        return Ros2Names.bridgeAnnouncement(context.session().zid(), kind, fullTopic, type.name(), qos, typeHash);
    }

    private String announce(long entityId, String kind, String fullTopic, Ros2MessageType type, QosProfile qos) {
        return dds() ? bridgeAnnouncement(kind, fullTopic, type, qos) : entityToken(entityId, kind, fullTopic, type, qos);
    }

    /**
     * @param topic absolute or relative (to the node's namespace) topic name
     * @return the fully qualified topic name
     */
    public String resolve(String topic) {
        return Ros2Names.resolveTopic(namespace, topic);
    }

    /**
     * Declares a publisher and its liveliness token.
     *
     * @param topic absolute or relative topic name
     * @param type the message type
     * @param qos the QoS profile announced in the token
     * @param maxMessageBytes the largest message it will publish
     * @return the publisher
     * @throws ZenohException if the declaration fails
     */
    public Ros2Publisher createPublisher(String topic, Ros2MessageType type, QosProfile qos, int maxMessageBytes)
            throws ZenohException {
        String full = resolve(topic);
        long id = context.nextId();
        ZenohPublisher p = context.session().declarePublisher(topicKey(full, type));
        String tokenKey = announce(id, PUBLISHER, full, type, qos);
        LivelinessToken token = context.session().declareToken(tokenKey);
        // the bridge forwards payloads only: no attachment, so no gid, on DDS
        return new Ros2Publisher(p, token, dds() ? null : Ros2Publisher.gid(tokenKey), maxMessageBytes);
    }

    /**
     * Declares a subscription and its liveliness token; samples go to {@code mailbox} tagged
     * with {@code channel}.
     *
     * @param topic absolute or relative topic name
     * @param type the message type (only samples of this type and hash match)
     * @param qos the QoS profile announced in the token
     * @param mailbox where samples go
     * @param channel their tag
     * @return the subscription's liveliness token
     * @throws ZenohException if the declaration fails
     */
    public LivelinessToken subscribe(String topic, Ros2MessageType type, QosProfile qos, ZenohMailbox mailbox,
                                     int channel) throws ZenohException {
        String full = resolve(topic);
        long id = context.nextId();
        mailbox.subscribe(topicKey(full, type), channel);
        return context.session().declareToken(announce(id, SUBSCRIPTION, full, type, qos));
    }

    /** @return the namespace */
    public String namespace() {
        return namespace;
    }

    /** @return the name */
    public String name() {
        return name;
    }

    /** @return the context */
    public Ros2Context context() {
        return context;
    }
}
