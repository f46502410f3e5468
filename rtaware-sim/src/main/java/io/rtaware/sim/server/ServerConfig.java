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
 * @param maxClients most clients connected at once (each costs two threads), 1..{@value #MAX_CLIENTS_LIMIT};
 *     more are refused
 * @param maxRulesPerClient most distinct replace rules per client, 1..65536; more are NACKed
 * @param messageTimeoutNs how long a client's message may take from its first bytes to its last
 *     (wall time), 1 ms .. 1 h; a client exceeding it is disconnected
 */
public record ServerConfig(String bindAddress, int port, String modelName, int queueLimit, long stepPeriodNs,
                           int maxRequestBytes, int maxClients, int maxRulesPerClient, long messageTimeoutNs) {

    /** The default bind address. */
    public static final String LOOPBACK = "127.0.0.1";
    /** Player's default port. */
    public static final int PLAYER_PORT = 6665;
    /** The default {@link #maxClients}. */
    public static final int DEFAULT_MAX_CLIENTS = 32;
    /** The largest {@link #maxClients} accepted. */
    public static final int MAX_CLIENTS_LIMIT = 4096;
    /** The default {@link #maxRulesPerClient} (Player's C client adds one or two). */
    public static final int DEFAULT_MAX_RULES = 64;
    /** The default {@link #messageTimeoutNs}: 10 s. */
    public static final long DEFAULT_MESSAGE_TIMEOUT_NS = 10_000_000_000L;

    /**
     * @param bindAddress the address to listen on; loopback ({@value #LOOPBACK}) by default
     * @param port the TCP port, 0..65535 (0 = any free port)
     * @param modelName the robot's model name for {@code simulation:0} requests, not blank
     * @param queueLimit most data messages held per client before the oldest is dropped, 1..65536
     * @param stepPeriodNs the world-time step the sim thread aims for, 1 us .. 1 s
     * @param maxRequestBytes largest message body accepted from a client, 64..16 MiB
     * @param maxClients most clients connected at once (each costs two threads), 1..{@value
     *     #MAX_CLIENTS_LIMIT}; more are refused
     * @param maxRulesPerClient most distinct replace rules per client, 1..65536; more are NACKed
     * @param messageTimeoutNs how long a client's message may take from its first bytes to its last (wall
     *     time), 1 ms .. 1 h; a client exceeding it is disconnected
     * @throws IllegalArgumentException naming the field and the value if one is out of range
     */
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
        if (maxClients < 1 || maxClients > MAX_CLIENTS_LIMIT) {
            throw new IllegalArgumentException("maxClients must be in 1.." + MAX_CLIENTS_LIMIT + ", got " + maxClients);
        }
        if (maxRulesPerClient < 1 || maxRulesPerClient > 65536) {
            throw new IllegalArgumentException("maxRulesPerClient must be in 1..65536, got " + maxRulesPerClient);
        }
        if (messageTimeoutNs < 1_000_000L || messageTimeoutNs > 3_600_000_000_000L) {
            throw new IllegalArgumentException("messageTimeoutNs must be in 1000000..3600000000000 (1 ms .. 1 h), got "
                    + messageTimeoutNs);
        }
    }

    /**
     * The first six settings, with the default client, rule and message-time limits.
     *
     * @param bindAddress see {@link #bindAddress}
     * @param port see {@link #port}
     * @param modelName see {@link #modelName}
     * @param queueLimit see {@link #queueLimit}
     * @param stepPeriodNs see {@link #stepPeriodNs}
     * @param maxRequestBytes see {@link #maxRequestBytes}
     */
    public ServerConfig(String bindAddress, int port, String modelName, int queueLimit, long stepPeriodNs,
                        int maxRequestBytes) {
        this(bindAddress, port, modelName, queueLimit, stepPeriodNs, maxRequestBytes, DEFAULT_MAX_CLIENTS,
                DEFAULT_MAX_RULES, DEFAULT_MESSAGE_TIMEOUT_NS);
    }

    /**
     * Loopback, the given port, model {@code r0}, 1024 queued messages (Player's queue length),
     * 10 ms world-time steps (100 Hz), 64 KiB requests, {@value #DEFAULT_MAX_CLIENTS} clients,
     * {@value #DEFAULT_MAX_RULES} replace rules per client, 10 s per message.
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
        return new ServerConfig(address, port, modelName, queueLimit, stepPeriodNs, maxRequestBytes, maxClients,
                maxRulesPerClient, messageTimeoutNs);
    }

    /**
     * @param clients new {@link #maxClients}
     * @param rulesPerClient new {@link #maxRulesPerClient}
     * @param messageTimeout new {@link #messageTimeoutNs}
     * @return a copy with other limits
     * @throws IllegalArgumentException if a limit is out of range
     */
    public ServerConfig withLimits(int clients, int rulesPerClient, long messageTimeout) {
        return new ServerConfig(bindAddress, port, modelName, queueLimit, stepPeriodNs, maxRequestBytes, clients,
                rulesPerClient, messageTimeout);
    }
}
