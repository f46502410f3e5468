package io.rtaware.player.client;

import io.rtaware.player.protocol.PlayerFrameReader;

/**
 * Connection settings of a {@link PlayerClient}. Validated on construction; immutable and
 * thread-safe.
 *
 * @param connectTimeoutMs how long to wait for the TCP connection and for the banner
 * @param requestTimeoutMs how long to wait for the reply to a request
 * @param maxBodyBytes largest message body accepted; a larger header size is a protocol error
 * @param scanCapacity most beams of a laser or ranger scan accepted
 */
public record PlayerClientOptions(int connectTimeoutMs, int requestTimeoutMs, int maxBodyBytes, int scanCapacity) {

    /**
      * @param connectTimeoutMs how long to wait for the TCP connection and for the banner
      * @param requestTimeoutMs how long to wait for the reply to a request
      * @param maxBodyBytes largest message body accepted; a larger header size is a protocol error
      * @param scanCapacity most beams of a laser or ranger scan accepted
     * @throws IllegalArgumentException if a value is not positive
      */
    public PlayerClientOptions {
        if (connectTimeoutMs <= 0 || requestTimeoutMs <= 0 || maxBodyBytes <= 0 || scanCapacity <= 0) {
            throw new IllegalArgumentException("Player client options must be positive: connectTimeoutMs="
                    + connectTimeoutMs + " requestTimeoutMs=" + requestTimeoutMs + " maxBodyBytes=" + maxBodyBytes
                    + " scanCapacity=" + scanCapacity);
        }
    }

    /** @return 2 s connect, 2 s request timeout, 4 MiB bodies, 4096 beams */
    public static PlayerClientOptions defaults() {
        return new PlayerClientOptions(2000, 2000, PlayerFrameReader.DEFAULT_MAX_BODY_BYTES, 4096);
    }
}
