package io.rtaware.player.task;

import io.rtaware.player.client.PlayerClientOptions;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.PlayerFrameReader;

/**
 * Configuration of a {@link PlayerDataTask}, validated once on construction. Immutable and
 * thread-safe.
 *
 * @param host Player server host
 * @param port Player server port (Player's default is 6665)
 * @param scanSource where scans come from: {@code laser:N} or {@code ranger:N}
 * @param position2dIndex index of the position2d device (odometry and motors)
 * @param dataMode PUSH (default, with a replace rule) or PULL
 * @param connectTimeoutMs TCP connect and banner timeout
 * @param requestTimeoutMs reply timeout of each request
 * @param readTimeoutMs wall time without any message after which the connection counts as
 *     lost (measured on the monitor's clock and converted to wall time, so a scaled world does
 *     not shorten it)
 * @param pollWaitMs longest wall time one {@code execute} waits for data, so the executor can
 *     stop the task
 * @param reconnect whether to reconnect after a loss
 * @param reconnectInitialBackoffMs first wait (world time) before reconnecting
 * @param reconnectMaxBackoffMs longest wait; the wait doubles after each failed attempt
 * @param keepAliveMs world time after which an unchanged motor command is sent again
 * @param maxBodyBytes largest message body accepted
 */
public record PlayerConfig(String host, int port, DeviceAddress scanSource, int position2dIndex, DataMode dataMode,
                           int connectTimeoutMs, int requestTimeoutMs, int readTimeoutMs, int pollWaitMs,
                           boolean reconnect, long reconnectInitialBackoffMs, long reconnectMaxBackoffMs,
                           long keepAliveMs, int maxBodyBytes) {

    /**
      * @param host Player server host
      * @param port Player server port (Player's default is 6665)
      * @param scanSource where scans come from: {@code laser:N} or {@code ranger:N}
      * @param position2dIndex index of the position2d device (odometry and motors)
      * @param dataMode PUSH (default, with a replace rule) or PULL
      * @param connectTimeoutMs TCP connect and banner timeout
      * @param requestTimeoutMs reply timeout of each request
      * @param readTimeoutMs wall time without any message after which the connection counts as lost (measured
      *     on the monitor's clock and converted to wall time, so a scaled world does not shorten it)
      * @param pollWaitMs longest wall time one {@code execute} waits for data, so the executor can stop the
      *     task
      * @param reconnect whether to reconnect after a loss
      * @param reconnectInitialBackoffMs first wait (world time) before reconnecting
      * @param reconnectMaxBackoffMs longest wait; the wait doubles after each failed attempt
      * @param keepAliveMs world time after which an unchanged motor command is sent again
      * @param maxBodyBytes largest message body accepted
     * @throws IllegalArgumentException naming every invalid field
      */
    public PlayerConfig {
        StringBuilder bad = new StringBuilder();
        if (host == null || host.isBlank()) {
            bad.append(" host is empty;");
        }
        if (port < 1 || port > 65535) {
            bad.append(" port ").append(port).append(" outside 1..65535;");
        }
        if (scanSource == null || (scanSource.interf() != Interfaces.LASER && scanSource.interf() != Interfaces.RANGER)) {
            bad.append(" scanSource ").append(scanSource).append(" is not a laser or ranger;");
        }
        if (position2dIndex < 0 || position2dIndex > 0xffff) {
            bad.append(" position2dIndex ").append(position2dIndex).append(" outside 0..65535;");
        }
        if (dataMode == null) {
            bad.append(" dataMode is null;");
        }
        if (connectTimeoutMs <= 0 || requestTimeoutMs <= 0 || readTimeoutMs <= 0 || pollWaitMs <= 0) {
            bad.append(" timeouts must be positive;");
        }
        if (reconnectInitialBackoffMs <= 0 || reconnectMaxBackoffMs < reconnectInitialBackoffMs) {
            bad.append(" reconnect back-off must be positive with max >= initial;");
        }
        if (keepAliveMs <= 0) {
            bad.append(" keepAliveMs must be positive;");
        }
        if (maxBodyBytes <= 0) {
            bad.append(" maxBodyBytes must be positive;");
        }
        if (bad.length() > 0) {
            throw new IllegalArgumentException("invalid Player configuration:" + bad);
        }
    }

    /**
     * Defaults: scans from {@code laser:0}, position2d 0, PUSH, 2 s connect and request
     * timeouts, 2 s read timeout, 20 ms poll wait, no reconnection (back-off 0.5 s to 8 s when
     * enabled), 500 ms keep-alive, 4 MiB bodies.
     *
     * @param host server host
     * @param port server port
     * @return the configuration
     */
    public static PlayerConfig of(String host, int port) {
        return new PlayerConfig(host, port, DeviceAddress.parse("laser:0"), 0, DataMode.PUSH, 2000, 2000, 2000, 20,
                false, 500, 8000, 500, PlayerFrameReader.DEFAULT_MAX_BODY_BYTES);
    }

    /**
     * @param source {@code laser:N} or {@code ranger:N}
     * @return a copy with another scan source
     */
    public PlayerConfig withScanSource(String source) {
        return new PlayerConfig(host, port, DeviceAddress.parse(source), position2dIndex, dataMode, connectTimeoutMs,
                requestTimeoutMs, readTimeoutMs, pollWaitMs, reconnect, reconnectInitialBackoffMs,
                reconnectMaxBackoffMs, keepAliveMs, maxBodyBytes);
    }

    /**
     * @param mode PUSH or PULL
     * @return a copy with another data mode
     */
    public PlayerConfig withDataMode(DataMode mode) {
        return new PlayerConfig(host, port, scanSource, position2dIndex, mode, connectTimeoutMs, requestTimeoutMs,
                readTimeoutMs, pollWaitMs, reconnect, reconnectInitialBackoffMs, reconnectMaxBackoffMs, keepAliveMs,
                maxBodyBytes);
    }

    /**
     * @param enabled whether to reconnect
     * @param initialBackoffMs first wait
     * @param maxBackoffMs longest wait
     * @return a copy with another reconnection policy
     */
    public PlayerConfig withReconnect(boolean enabled, long initialBackoffMs, long maxBackoffMs) {
        return new PlayerConfig(host, port, scanSource, position2dIndex, dataMode, connectTimeoutMs, requestTimeoutMs,
                readTimeoutMs, pollWaitMs, enabled, initialBackoffMs, maxBackoffMs, keepAliveMs, maxBodyBytes);
    }

    /**
     * @param connectMs connect and banner timeout
     * @param requestMs request timeout
     * @param readMs read timeout (world time)
     * @return a copy with other timeouts
     */
    public PlayerConfig withTimeouts(int connectMs, int requestMs, int readMs) {
        return new PlayerConfig(host, port, scanSource, position2dIndex, dataMode, connectMs, requestMs, readMs,
                pollWaitMs, reconnect, reconnectInitialBackoffMs, reconnectMaxBackoffMs, keepAliveMs, maxBodyBytes);
    }

    /**
     * @param periodMs keep-alive period in world milliseconds
     * @return a copy with another keep-alive period
     */
    public PlayerConfig withKeepAliveMs(long periodMs) {
        return new PlayerConfig(host, port, scanSource, position2dIndex, dataMode, connectTimeoutMs, requestTimeoutMs,
                readTimeoutMs, pollWaitMs, reconnect, reconnectInitialBackoffMs, reconnectMaxBackoffMs, periodMs,
                maxBodyBytes);
    }

    /** @return the client options these settings imply */
    public PlayerClientOptions clientOptions() {
        return new PlayerClientOptions(connectTimeoutMs, requestTimeoutMs, maxBodyBytes, 4096);
    }
}
