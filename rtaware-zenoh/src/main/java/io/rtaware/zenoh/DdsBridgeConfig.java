package io.rtaware.zenoh;

import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.util.Map;
import java.util.Objects;

/**
 * What a {@link DdsBridge} is told: where its Zenoh runtime listens, the plugin's settings, the
 * Cyclone DDS configuration, the one network interface its sockets are held to, and the
 * environment of its process. Every value is text the caller decided; nothing here knows ROS 2.
 * Immutable.
 *
 * @param listen where the bridge's runtime listens ({@code tcp/127.0.0.1:0} for a free loopback port)
 * @param pluginConfig the plugin's settings, JSON5 (the {@code plugins/ros2dds} section of a
 *     {@code zenoh-bridge-ros2dds} configuration); its {@code domain} is the DDS domain the bridge
 *     creates
 * @param cycloneConfig the whole Cyclone DDS configuration, in the form {@code CYCLONEDDS_URI} takes
 *     (XML fragments and file names, comma-separated; empty for Cyclone's defaults): the bridge
 *     creates its DDS domain with it, and Cyclone DDS reads nothing else
 * @param bindInterface the network interface every socket of the bridge is held to (its IPv4
 *     address, or the interface itself for a multicast receiver), or null to let Cyclone DDS bind
 *     as it does by itself: its receive sockets on every address of the machine
 * @param environment variables of the bridge's process beyond those of this one (the plugin reads
 *     {@code ROS_DISTRO}); {@code CYCLONEDDS_URI} is never passed on, {@code cycloneConfig} replaces it
 */
public record DdsBridgeConfig(String listen, String pluginConfig, String cycloneConfig, String bindInterface,
                              Map<String, String> environment) {

    /**
     * @param listen where the bridge's runtime listens
     * @param pluginConfig the plugin's settings, JSON5
     * @param cycloneConfig the whole Cyclone DDS configuration
     * @param bindInterface the interface the bridge's sockets are held to, or null
     * @param environment variables of the bridge's process
     * @throws IllegalArgumentException for a malformed listen endpoint
     */
    public DdsBridgeConfig {
        ZenohConfig.checkEndpoint(listen, true);
        Objects.requireNonNull(pluginConfig, "pluginConfig");
        Objects.requireNonNull(cycloneConfig, "cycloneConfig");
        environment = Map.copyOf(environment);
    }

    /**
     * The address a bridge held to an interface binds its sockets to.
     *
     * @param name a network interface's name ({@code lo}, {@code eth0})
     * @return its first IPv4 address ({@code 127.0.0.1})
     * @throws IllegalArgumentException naming the interface, when this machine has none of that
     *     name or it has no IPv4 address
     */
    public static String interfaceAddress(String name) {
        NetworkInterface network;
        try {
            network = NetworkInterface.getByName(name);
        } catch (SocketException e) {
            throw new IllegalArgumentException("cannot list the network interfaces to find '" + name + "': " + e.getMessage());
        }
        if (network == null) {
            throw new IllegalArgumentException("no network interface named '" + name + "' on this machine");
        }
        return network.inetAddresses().filter(Inet4Address.class::isInstance).map(InetAddress::getHostAddress).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("network interface '" + name + "' has no IPv4 address"));
    }
}
