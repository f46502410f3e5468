package io.rtaware.foxglove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** {@code --foxglove [HOST:]PORT}: a bare port is loopback; anything else says what it wanted. */
class FoxgloveAddressTest {

    @Test
    void aBarePortBindsLoopbackOnly() {
        assertEquals(new FoxgloveAddress("127.0.0.1", 8765), FoxgloveAddress.parse("8765"));
        assertEquals(new FoxgloveAddress("127.0.0.1", 0), FoxgloveAddress.parse("0"));
    }

    @Test
    void aHostIsKeptAsGiven() {
        assertEquals(new FoxgloveAddress("0.0.0.0", 9000), FoxgloveAddress.parse("0.0.0.0:9000"));
        assertEquals(new FoxgloveAddress("localhost", 65535), FoxgloveAddress.parse("localhost:65535"));
    }

    @Test
    void anIpv6AddressIsWrittenInBrackets() {
        FoxgloveAddress a = FoxgloveAddress.parse("[::1]:8765");
        assertEquals(new FoxgloveAddress("::1", 8765), a);
        assertEquals("[::1]:8765", a.toString(), "printed the way it is given");
        assertEquals("127.0.0.1:8765", FoxgloveAddress.parse("8765").toString());
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "abc", "70000", "65536", "-1", "host:", ":8765", "::1:8765", "8765x", "[::1]8765",
        "[]:8765", "1234567", " 8765", "localhost:port"})
    void anythingElseIsOneLineNamingTheValue(String text) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FoxgloveAddress.parse(text));
        assertEquals(1, e.getMessage().lines().count(), "one line: " + e.getMessage());
        assertTrue(e.getMessage().contains("'" + text + "'"), "names the value: " + e.getMessage());
        assertTrue(e.getMessage().contains("[HOST:]PORT"), "says what it wanted: " + e.getMessage());
    }
}
