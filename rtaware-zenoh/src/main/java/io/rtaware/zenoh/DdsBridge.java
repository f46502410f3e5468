package io.rtaware.zenoh;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * ZettaScale's ROS 2 DDS bridge ({@code zenoh-plugin-ros2dds}, on Eclipse Cyclone DDS) running in
 * a Zenoh runtime of its own inside this process (issue 29). The runtime listens on one endpoint;
 * sessions that connect to it reach the DDS domain the plugin joined: the plugin maps a DDS topic
 * {@code rt/scan} to the key {@code scan}, and creates DDS writers and readers for the routes that
 * sessions announce by liveliness tokens the way one bridge announces its routes to another.
 *
 * <p>What the plugin and Cyclone DDS are told (domain, interfaces, discovery) is decided by the
 * caller and passed as text: the plugin's configuration and the environment they read when they
 * start ({@code ROS_DISTRO}, {@code CYCLONEDDS_URI}). The environment is the process's: set once,
 * before the plugin starts, and the plugin's DDS participant lives until the process ends (the
 * plugin has no stop); closing the bridge ends its Zenoh side. Thread-safe.
 */
public final class DdsBridge implements AutoCloseable {

    private final String zid;
    private final List<String> endpoints;
    private long handle;

    private DdsBridge(long handle, String zid, List<String> endpoints) {
        this.handle = handle;
        this.zid = zid;
        this.endpoints = endpoints;
    }

    /**
     * @return why the bridge cannot start in this process (the native layer is missing, or was
     *     built without the bridge), or null when it can
     */
    public static String unavailableReason() {
        String reason = ZenohLibrary.unavailableReason();
        if (reason != null) {
            return reason;
        }
        return NativeZenoh.ddsAvailable() ? null
                : "the native Zenoh layer was built without the ROS 2 DDS bridge (building it needs cmake and "
                        + "libclang-dev; rebuild with both installed)";
    }

    /**
     * Starts the bridge.
     *
     * @param listen where its runtime listens ({@code tcp/127.0.0.1:0} for a free loopback port)
     * @param pluginConfig the plugin's settings, JSON5 (the {@code plugins/ros2dds} section of a
     *     {@code zenoh-bridge-ros2dds} configuration)
     * @param environment variables to set before the plugin starts (an empty value removes one)
     * @return the running bridge
     * @throws ZenohException if the bridge is not in this build, or the runtime cannot start
     */
    public static DdsBridge start(String listen, String pluginConfig, Map<String, String> environment)
            throws ZenohException {
        ZenohConfig.checkEndpoint(listen, true);
        Objects.requireNonNull(pluginConfig, "pluginConfig");
        String reason = unavailableReason();
        if (reason != null) {
            throw new ZenohException(reason);
        }
        List<String> pairs = new ArrayList<>();
        environment.forEach((name, value) -> {
            pairs.add(name);
            pairs.add(value);
        });
        long h = NativeZenoh.startDdsBridge(listen, pluginConfig, pairs.toArray(String[]::new));
        try {
            String[] info = NativeZenoh.ddsBridgeInfo(h);
            return new DdsBridge(h, info[0], List.of(info).subList(1, info.length));
        } catch (ZenohException | RuntimeException e) {
            NativeZenoh.closeDdsBridge(h);
            throw e;
        }
    }

    /** @return the Zenoh id of the bridge's runtime (lowercase hexadecimal) */
    public String zid() {
        return zid;
    }

    /** @return the endpoints its runtime listens on, as Zenoh prints them ({@code tcp/127.0.0.1:40123}) */
    public List<String> endpoints() {
        return endpoints;
    }

    /**
     * @return the first endpoint a session on this machine can connect to
     * @throws IllegalStateException if the runtime listens on none
     */
    public String endpoint() {
        return endpoints.stream().filter(e -> e.startsWith("tcp/")).findFirst()
                .orElseThrow(() -> new IllegalStateException("the DDS bridge listens on no TCP endpoint: " + endpoints));
    }

    /**
     * Closes the bridge's runtime. Idempotent.
     *
     * @throws ZenohException if the runtime fails to close
     */
    @Override
    public synchronized void close() throws ZenohException {
        if (handle != 0) {
            long h = handle;
            handle = 0;
            NativeZenoh.closeDdsBridge(h);
        }
    }
}
