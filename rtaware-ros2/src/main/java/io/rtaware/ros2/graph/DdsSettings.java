package io.rtaware.ros2.graph;

import java.io.File;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
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
 * {@code ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST}, and {@code ROS_LOCALHOST_ONLY=1} on Humble).
 * One setting opens it to a robot's network: the interface name ({@code --dds-interface eth0}),
 * on which Cyclone DDS then discovers by multicast as a stock ROS 2 node does. A user's own
 * {@code CYCLONEDDS_URI} replaces both: the bridge then adds nothing to it. Immutable.
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
     * @return the plugin's settings (JSON): the domain, the bridge's node name, and the discovery
     *     range (Iron and later) or localhost-only switch (Humble) matching {@link #confined()};
     *     with a user's {@code CYCLONEDDS_URI} the plugin is told to add nothing to it
     */
    public String pluginConfig() {
        StringBuilder json = new StringBuilder("{\"domain\": ").append(domain)
                .append(", \"namespace\": \"/\", \"nodename\": \"").append(BRIDGE_NODE).append('"');
        if (distro == Ros2Distro.HUMBLE) {
            json.append(", \"ros_localhost_only\": ").append(confined());
        } else {
            String range = userCycloneUri != null ? "SYSTEM_DEFAULT" : confined() ? "LOCALHOST" : "SUBNET";
            json.append(", \"ros_localhost_only\": false, \"ros_automatic_discovery_range\": \"").append(range).append('"');
        }
        return json.append('}').toString();
    }

    /**
     * @return the environment the plugin and Cyclone DDS read when they start: {@code ROS_DISTRO}
     *     (the plugin's discovery differs before Iron) and {@code CYCLONEDDS_URI}: the user's as
     *     it is, or a fragment that pins the interface (and, on loopback, turns multicast off and
     *     names 127.0.0.1 as the unicast peer). The plugin puts its own fragment in front of it;
     *     Cyclone DDS lets later fragments override earlier ones.
     */
    public Map<String, String> environment() {
        Map<String, String> env = new LinkedHashMap<>();
        env.put("ROS_DISTRO", distro.cliName());
        env.put("CYCLONEDDS_URI", userCycloneUri != null ? userCycloneUri : cycloneFragment());
        return env;
    }

    private String cycloneFragment() {
        StringBuilder xml = new StringBuilder("<CycloneDDS><Domain><General><Interfaces><NetworkInterface name=\"")
                .append(networkInterface).append("\"/></Interfaces>");
        if (LOOPBACK.equals(networkInterface)) {
            xml.append("<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
                    + "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex><Peers><Peer address=\"127.0.0.1\"/></Peers>"
                    + "</Discovery>");
        } else {
            xml.append("</General>");
        }
        return xml.append("</Domain></CycloneDDS>").toString();
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
