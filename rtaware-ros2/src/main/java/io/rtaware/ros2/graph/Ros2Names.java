package io.rtaware.ros2.graph;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * ROS 2 names as rmw_zenoh puts them into key expressions and liveliness tokens. Stateless.
 */
public final class Ros2Names {

    private static final Pattern NAME = Pattern.compile("(/[A-Za-z_][A-Za-z0-9_]*)*");
    private static final Pattern NODE = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");
    private static final Pattern DDS_TYPE = Pattern.compile("([A-Za-z0-9_]+(?:::[A-Za-z0-9_]+)*)::dds_::([A-Za-z0-9_]+)_");

    private Ros2Names() {
    }

    /**
     * @param namespace {@code /} or {@code /robot1} (a missing leading slash is added, a
     *     trailing one removed)
     * @return the namespace in canonical form
     * @throws IllegalArgumentException if it is not a valid ROS 2 namespace
     */
    public static String namespace(String namespace) {
        String ns = namespace == null || namespace.isEmpty() ? "/" : namespace;
        ns = ns.startsWith("/") ? ns : "/" + ns;
        ns = ns.length() > 1 && ns.endsWith("/") ? ns.substring(0, ns.length() - 1) : ns;
        if (!ns.equals("/") && !NAME.matcher(ns).matches()) {
            throw new IllegalArgumentException("invalid ROS 2 namespace '" + namespace + "'");
        }
        return ns;
    }

    /**
     * @param namespace a canonical namespace
     * @param topic an absolute ({@code /scan}) or relative ({@code scan}) topic name
     * @return the fully qualified topic name (a relative name is put under the namespace)
     * @throws IllegalArgumentException if the topic is not a valid ROS 2 name
     */
    public static String resolveTopic(String namespace, String topic) {
        if (topic == null || topic.isEmpty() || topic.endsWith("/")) {
            throw new IllegalArgumentException("invalid ROS 2 topic name '" + topic + "'");
        }
        String full = topic.startsWith("/") ? topic : (namespace.equals("/") ? "" : namespace) + "/" + topic;
        if (!NAME.matcher(full).matches()) {
            throw new IllegalArgumentException("invalid ROS 2 topic name '" + topic + "'");
        }
        return full;
    }

    /**
     * @param name a node name
     * @return the name
     * @throws IllegalArgumentException if it is not a valid ROS 2 node name
     */
    public static String nodeName(String name) {
        if (name == null || !NODE.matcher(name).matches()) {
            throw new IllegalArgumentException("invalid ROS 2 node name '" + name + "'");
        }
        return name;
    }

    /**
     * The topic key expression: {@code <domain>/<topic without its leading slash>/<dds type>/<hash>}.
     *
     * @param domain the ROS domain id
     * @param fullTopic a fully qualified topic name
     * @param ddsTypeName e.g. {@code geometry_msgs::msg::dds_::Twist_}
     * @param typeHash e.g. {@code RIHS01_9c45...}
     * @return the key expression
     */
    public static String topicKey(int domain, String fullTopic, String ddsTypeName, String typeHash) {
        return domain + "/" + fullTopic.substring(1) + "/" + ddsTypeName + "/" + typeHash;
    }

    /**
     * The key the ROS 2 DDS bridge ({@code zenoh-plugin-ros2dds}, namespace {@code /}) maps a
     * topic to: its name without the leading slash ({@code /robot1/scan} is DDS's
     * {@code rt/robot1/scan} and Zenoh's {@code robot1/scan}).
     *
     * @param fullTopic a fully qualified topic name
     * @return the key expression
     */
    public static String bridgeKey(String fullTopic) {
        return fullTopic.substring(1);
    }

    /**
     * A route announcement to the ROS 2 DDS bridge, as one {@code zenoh-plugin-ros2dds} announces its
     * routes to another: {@code @/<zid>/@ros2_lv/<MP|MS>/<key>/<ROS type>/<QoS>[:typehash=<hash>;]}
     * with every {@code /} inside the key and the type written {@code §}; the type hash (Iron on) is
     * the user data ROS 2 puts in DDS's USER_DATA QoS. The bridge answers a publisher's announcement
     * ({@code MP}) with a DDS writer, a subscription's ({@code MS}) with a DDS reader.
     *
     * @param zid the announcing session's Zenoh id
     * @param kind {@code MP} or {@code MS}
     * @param fullTopic a fully qualified topic name
     * @param rosType the ROS type name, e.g. {@code sensor_msgs/msg/LaserScan}
     * @param qos the QoS profile
     * @param typeHash the type's {@code RIHS01_...} hash, or null for none (Humble)
     * @return the liveliness key
     */
    public static String bridgeAnnouncement(String zid, String kind, String fullTopic, String rosType, QosProfile qos,
                                            String typeHash) {
        return "@/" + zid + "/@ros2_lv/" + kind + "/" + bridgeKey(fullTopic).replace("/", "§") + "/"
                + rosType.replace("/", "§") + "/" + qos.bridgeText() + (typeHash == null ? "" : ":typehash=" + typeHash + ";");
    }

    /**
     * A DDS type name as ROS 2 names the type: {@code geometry_msgs::msg::dds_::Twist_} is
     * {@code geometry_msgs/msg/Twist}; a name that is not of that form (a plain DDS application's
     * type) is returned as it is.
     *
     * @param ddsTypeName a DDS type name
     * @return the ROS 2 type name, or the name as it is
     */
    public static String rosTypeName(String ddsTypeName) {
        Matcher m = DDS_TYPE.matcher(ddsTypeName);
        return m.matches() ? m.group(1).replace("::", "/") + "/" + m.group(2) : ddsTypeName;
    }

    /**
     * A name as a single segment of a liveliness token: every {@code /} becomes {@code %}, and an
     * empty name is a single {@code %}.
     *
     * @param name the name
     * @return the mangled name
     */
    public static String mangle(String name) {
        return name.isEmpty() ? "%" : name.replace('/', '%');
    }
}
