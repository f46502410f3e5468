package io.rtaware.foxglove;

/**
 * Where the Foxglove server listens, as {@code --foxglove [HOST:]PORT} gives it: a bare port
 * binds {@value #LOOPBACK} (this machine only); a host exposes it deliberately
 * ({@code 0.0.0.0:8765}); an IPv6 address is written in brackets ({@code [::1]:8765}).
 *
 * @param host the host name or address to bind
 * @param port the TCP port, 0 for a free one
 */
public record FoxgloveAddress(String host, int port) {

    /** The host a bare port binds: this machine only. */
    public static final String LOOPBACK = "127.0.0.1";

    /** foxglove_bridge's port, the one Foxglove offers first. */
    public static final int DEFAULT_PORT = 8765;

    private static final String FORM = " is not [HOST:]PORT (e.g. " + DEFAULT_PORT + ", 0.0.0.0:" + DEFAULT_PORT
            + ", [::1]:" + DEFAULT_PORT + "; port 0..65535, 0 for a free one)";

    /**
     * Validates the fields.
     *
     * @param host the host name or address to bind
     * @param port the TCP port, 0 for a free one
     */
    public FoxgloveAddress {
        if (host == null || host.isEmpty()) {
            throw new IllegalArgumentException("the host must not be empty");
        }
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("the port must be 0..65535, got " + port);
        }
    }

    /**
     * Reads {@code [HOST:]PORT}.
     *
     * @param text e.g. {@code 8765}, {@code 0.0.0.0:8765}, {@code [::1]:8765}
     * @return the address
     * @throws IllegalArgumentException with one line naming the value, if it is not of that form
     */
    public static FoxgloveAddress parse(String text) {
        if (text == null) {
            throw new IllegalArgumentException("'' " + FORM);
        }
        String host;
        String port;
        if (text.startsWith("[")) {
            int close = text.indexOf("]:");
            if (close < 2) {
                throw new IllegalArgumentException("'" + text + "'" + FORM);
            }
            host = text.substring(1, close);
            port = text.substring(close + 2);
        } else {
            int colon = text.lastIndexOf(':');
            host = colon < 0 ? LOOPBACK : text.substring(0, colon);
            port = text.substring(colon + 1);
            if (host.isEmpty() || host.indexOf(':') >= 0) {
                throw new IllegalArgumentException("'" + text + "'" + FORM);
            }
        }
        if (port.isEmpty() || port.length() > 5 || !port.chars().allMatch(c -> c >= '0' && c <= '9')) {
            throw new IllegalArgumentException("'" + text + "'" + FORM);
        }
        int number = Integer.parseInt(port);
        if (number > 65535) {
            throw new IllegalArgumentException("'" + text + "'" + FORM);
        }
        return new FoxgloveAddress(host, number);
    }

    /** @return {@code HOST:PORT}, an IPv6 address in brackets */
    @Override
    public String toString() {
        return (host.indexOf(':') >= 0 ? "[" + host + "]" : host) + ":" + port;
    }
}
