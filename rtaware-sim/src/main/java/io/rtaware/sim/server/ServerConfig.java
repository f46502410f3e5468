package io.rtaware.sim.server;

/**
 * Settings of a {@link PlayerSimServer}. Immutable, validated, thread-safe.
 *
 * @param bindAddress the address to listen on; loopback ({@value #LOOPBACK}) by default
 * @param port the TCP port, 0..65535 (0 = any free port)
 * @param modelName the robot's model name for {@code simulation:0} requests, not blank
 * @param queueLimit most data messages held per client before the oldest is dropped, 1..65536
 * @param stepPeriodNs the world-time step the sim thread aims for, 1 us .. 1 s
 * @param maxRequestBytes largest message body accepted from a client, 64..16 MiB
 */
public record ServerConfig(String bindAddress, int port, String modelName, int queueLimit, long stepPeriodNs,
                           int maxRequestBytes) {

    /** The default bind address. */
    public static final String LOOPBACK = "127.0.0.1";
    /** Player's default port. */
    public static final int PLAYER_PORT = 6665;

    /** @throws IllegalArgumentException naming the field and the value if one is out of range */
    public ServerConfig {
        if (bindAddress == null || bindAddress.isBlank()) {
            throw new IllegalArgumentException("bindAddress must not be blank, got '" + bindAddress + "'");
        }
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be in 0..65535, got " + port);
        }
        if (modelName == null || modelName.isBlank() || modelName.length() > 255) {
            throw new IllegalArgumentException("modelName must be 1..255 characters, got '" + modelName + "'");
        }
        if (queueLimit < 1 || queueLimit > 65536) {
            throw new IllegalArgumentException("queueLimit must be in 1..65536, got " + queueLimit);
        }
        if (stepPeriodNs < 1_000L || stepPeriodNs > 1_000_000_000L) {
            throw new IllegalArgumentException("stepPeriodNs must be in 1000..1000000000, got " + stepPeriodNs);
        }
        if (maxRequestBytes < 64 || maxRequestBytes > (16 << 20)) {
            throw new IllegalArgumentException("maxRequestBytes must be in 64..16777216, got " + maxRequestBytes);
        }
    }

    /**
     * Loopback, the given port, model {@code r0}, 1024 queued messages (Player's queue length),
     * 10 ms world-time steps (100 Hz), 64 KiB requests.
     *
     * @param port the TCP port (0 = any free port)
     * @return the configuration
     */
    public static ServerConfig defaults(int port) {
        return new ServerConfig(LOOPBACK, port, "r0", 1024, 10_000_000L, 64 << 10);
    }

    /**
     * @param address new {@link #bindAddress}
     * @return a copy listening on another address
     */
    public ServerConfig withBindAddress(String address) {
        return new ServerConfig(address, port, modelName, queueLimit, stepPeriodNs, maxRequestBytes);
    }
}
