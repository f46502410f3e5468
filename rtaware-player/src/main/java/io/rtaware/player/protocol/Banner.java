package io.rtaware.player.protocol;

import io.rtaware.player.xdr.PlayerProtocolException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * The 32-byte banner a Player server sends right after accepting a connection:
 * {@code "Player v." + version}, NUL padded, no newline. Stateless; thread-safe.
 */
public final class Banner {

    /** Banner length in bytes. */
    public static final int SIZE_BYTES = 32;
    /** The banner's fixed prefix. */
    public static final String PREFIX = "Player v.";

    private Banner() {
    }

    /**
     * @param version the version to announce, e.g. {@code 3.1.1-dev}
     * @return the 32 banner bytes
     * @throws IllegalArgumentException if the text does not fit in 32 bytes
     */
    public static byte[] encode(String version) {
        byte[] text = (PREFIX + version).getBytes(StandardCharsets.US_ASCII);
        if (text.length > SIZE_BYTES) {
            throw new IllegalArgumentException("version '" + version + "' too long for the 32-byte banner");
        }
        return Arrays.copyOf(text, SIZE_BYTES);
    }

    /**
     * Checks a banner and extracts the version.
     *
     * @param bytes what the peer sent
     * @param length how many bytes were received (32 for a complete banner)
     * @return the version text after {@code Player v.}
     * @throws PlayerProtocolException if the bytes are not a Player banner; the message shows
     *     what was received, printable
     */
    public static String decode(byte[] bytes, int length) throws PlayerProtocolException {
        int n = Math.min(length, bytes.length);
        byte[] prefix = PREFIX.getBytes(StandardCharsets.US_ASCII);
        boolean matches = n >= prefix.length;
        for (int i = 0; matches && i < prefix.length; i++) {
            matches = bytes[i] == prefix[i];
        }
        if (!matches || n < SIZE_BYTES) {
            throw new PlayerProtocolException(0, "banner", "not a Player server: expected a 32-byte banner starting '"
                    + PREFIX + "', received " + n + " bytes: " + printable(bytes, n));
        }
        int end = prefix.length;
        while (end < SIZE_BYTES && bytes[end] != 0) {
            end++;
        }
        return new String(bytes, prefix.length, end - prefix.length, StandardCharsets.US_ASCII);
    }

    /**
     * Renders bytes for an error message: printable ASCII as is, everything else as
     * {@code \xNN}, in double quotes.
     *
     * @param bytes the bytes
     * @param length how many to show
     * @return the rendering
     */
    public static String printable(byte[] bytes, int length) {
        StringBuilder sb = new StringBuilder(length + 2).append('"');
        for (int i = 0; i < length; i++) {
            int b = bytes[i] & 0xff;
            if (b >= 0x20 && b < 0x7f && b != '"' && b != '\\') {
                sb.append((char) b);
            } else {
                sb.append(String.format("\\x%02x", b));
            }
        }
        return sb.append('"').toString();
    }
}
