package io.rtaware.ros2.graph;

import io.rtaware.zenoh.DdsBridgeConfig;
import java.io.File;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.regex.Pattern;

/**
 * How rtaware joins a DDS ROS 2 graph through the ROS 2 DDS bridge (issue 29): the DDS domain, the
 * ROS 2 distribution the bridge behaves as, and how far DDS may reach.
 *
 * <p>By default DDS stays on this machine: Cyclone DDS uses the loopback interface only, sends no
 * multicast, and discovers participants by unicast to 127.0.0.1 (what ROS 2 calls
 * {@code ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST}, and {@code ROS_LOCALHOST_ONLY=1} on Humble),
 * and the bridge's sockets are bound to 127.0.0.1. One setting opens it to a robot's network: the
 * interface name ({@code --dds-interface eth0}), on which Cyclone DDS then discovers by multicast
 * as a stock ROS 2 node does, its sockets held to that interface. A user's own
 * {@code CYCLONEDDS_URI} replaces both: the bridge then adds nothing to it and Cyclone DDS binds
 * as it does by itself (its receive sockets on every address). Immutable.
 *
 * @param domain the DDS domain (the ROS domain id, 0..232)
 * @param distro the distribution the bridge behaves as (Humble's discovery differs from Iron's on)
 * @param networkInterface the one interface DDS uses; {@value #LOOPBACK} keeps it on this machine
 * @param userCycloneUri the user's {@code CYCLONEDDS_URI}, used as it is, or null
 */
public record DdsSettings(int domain, Ros2Distro distro, String networkInterface, String userCycloneUri) {

    /** The loopback interface: where DDS stays unless told otherwise. */
    public static final String LOOPBACK = "lo";
    /** The node name under which the bridge appears in the ROS graph. */
    public static final String BRIDGE_NODE = "rtaware_dds_bridge";

    private static final Pattern INTERFACE = Pattern.compile("[A-Za-z0-9_.:@-]{1,15}");

    /**
     * @param domain the DDS domain, 0..232
     * @param distro the distribution the bridge behaves as
     * @param networkInterface the one interface DDS uses
     * @param userCycloneUri the user's {@code CYCLONEDDS_URI}, or null
     * @throws IllegalArgumentException naming the value: a domain outside 0..232, a malformed
     *     interface name, or a {@code CYCLONEDDS_URI} naming a file that cannot be read
     */
    public DdsSettings {
        Ros2Context.checkDomain(domain);
        Objects.requireNonNull(distro, "distro");
        if (networkInterface == null || !INTERFACE.matcher(networkInterface).matches()) {
            throw new IllegalArgumentException("malformed network interface name '" + networkInterface + "'");
        }
        if (userCycloneUri != null && userCycloneUri.isBlank()) {
            userCycloneUri = null;
        }
        if (userCycloneUri != null) {
            checkReadable(userCycloneUri);
        }
    }

    /**
     * Settings confined to this machine.
     *
     * @param domain the DDS domain
     * @param distro the distribution
     * @param environment the process environment ({@code CYCLONEDDS_URI} is taken from it)
     * @return the settings
     */
    public static DdsSettings loopback(int domain, Ros2Distro distro, Map<String, String> environment) {
        return new DdsSettings(domain, distro, LOOPBACK, environment.get("CYCLONEDDS_URI"));
    }

    /** @return whether DDS is kept on this machine (no user configuration, the loopback interface) */
    public boolean confined() {
        return userCycloneUri == null && LOOPBACK.equals(networkInterface);
    }

    /**
     * @return the plugin's settings (JSON): the domain, the bridge's node name, and that the
     *     plugin adds nothing to the Cyclone DDS configuration ({@link #cycloneConfig()} is whole;
     *     the plugin's own additions, from its discovery-range settings, would otherwise go into
     *     {@code CYCLONEDDS_URI})
     */
    public String pluginConfig() {
        StringBuilder json = new StringBuilder("{\"domain\": ").append(domain)
                .append(", \"namespace\": \"/\", \"nodename\": \"").append(BRIDGE_NODE)
                .append("\", \"ros_localhost_only\": false");
        if (distro != Ros2Distro.HUMBLE) {
            json.append(", \"ros_automatic_discovery_range\": \"SYSTEM_DEFAULT\"");
        }
        return json.append('}').toString();
    }

    /**
     * @return the environment of the bridge's process: {@code ROS_DISTRO}, which the plugin reads
     *     (its discovery differs before Iron)
     */
    public Map<String, String> environment() {
        return Map.of("ROS_DISTRO", distro.cliName());
    }

    /**
     * @return the whole Cyclone DDS configuration: the user's {@code CYCLONEDDS_URI} as it is, or
     *     one that pins the interface and, on loopback, turns multicast off and names 127.0.0.1 as
     *     the unicast peer (what ROS 2's {@code LOCALHOST} discovery range asks of Cyclone DDS);
     *     on another interface from Iron on, participant indexes as ROS 2's {@code SUBNET} range
     *     sets them
     */
    public String cycloneConfig() {
        if (userCycloneUri != null) {
            return userCycloneUri;
        }
        StringBuilder xml = new StringBuilder("<CycloneDDS><Domain><General><Interfaces><NetworkInterface name=\"")
                .append(networkInterface).append("\"/></Interfaces>");
        String autoIndex = "<ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>";
        if (LOOPBACK.equals(networkInterface)) {
            xml.append("<AllowMulticast>false</AllowMulticast></General><Discovery>").append(autoIndex)
                    .append("<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>");
        } else if (distro != Ros2Distro.HUMBLE) {
            xml.append("</General><Discovery>").append(autoIndex).append("</Discovery>");
        } else {
            xml.append("</General>");
        }
        return xml.append("</Domain></CycloneDDS>").toString();
    }

    /**
     * @return the interface every socket of the bridge is held to (the chosen one), or null with a
     *     user's {@code CYCLONEDDS_URI}, whose interfaces rtaware does not know
     */
    public String bindInterface() {
        return userCycloneUri != null ? null : networkInterface;
    }

    /**
     * @param listen where the bridge's runtime listens
     * @return what the bridge is told
     */
    public DdsBridgeConfig bridgeConfig(String listen) {
        return new DdsBridgeConfig(listen, pluginConfig(), cycloneConfig(), bindInterface(), environment());
    }

    /**
     * @return one line for a report: the domain and where DDS reaches
     */
    public String describe() {
        String reach = userCycloneUri != null ? "configured by CYCLONEDDS_URI"
                : confined() ? "loopback only, no multicast" : "interface " + networkInterface + ", multicast discovery";
        return String.format(Locale.ROOT, "DDS domain %d (%s) through zenoh-plugin-ros2dds", domain, reach);
    }

    /**
     * Checks the files a {@code CYCLONEDDS_URI} names: inline XML (starting with {@code <}) is
     * left to Cyclone DDS; every other comma-separated entry is a {@code file://} URI or a path
     * that must be a readable file.
     */
    private static void checkReadable(String uris) {
        for (String entry : uris.split(",")) {
            String item = entry.trim();
            if (item.isEmpty() || item.startsWith("<")) {
                continue;
            }
            Path path;
            try {
                path = item.startsWith("file:") ? Path.of(URI.create(item)) : new File(item).toPath();
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("CYCLONEDDS_URI: malformed entry '" + item + "'");
            }
            if (!Files.isRegularFile(path) || !Files.isReadable(path)) {
                throw new IllegalArgumentException("CYCLONEDDS_URI: cannot read '" + item + "'");
            }
        }
    }
}
