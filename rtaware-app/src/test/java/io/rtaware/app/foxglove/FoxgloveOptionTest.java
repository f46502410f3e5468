package io.rtaware.app.foxglove;

import io.rtaware.app.CliRun;
import java.net.InetAddress;
import java.net.ServerSocket;
import org.junit.jupiter.api.Test;

/** {@code --foxglove} on run, bench and sim: a bad value or a taken port is one line and exit status 2. */
class FoxgloveOptionTest {

    @Test
    void aValueThatIsNotHostAndPortIsOneLineOnRun() {
        CliRun.of("run", "--foxglove", "abc").assertOneLineUserError("--foxglove: 'abc' is not [HOST:]PORT");
    }

    @Test
    void aPortOutOfRangeIsOneLineOnBench() {
        CliRun.of("bench", "--duration", "1s", "--foxglove", "70000")
                .assertOneLineUserError("--foxglove: '70000' is not [HOST:]PORT");
    }

    @Test
    void aBareIpv6AddressIsOneLineOnSim() {
        CliRun.of("sim", "--port", "0", "--foxglove", "::1:8765")
                .assertOneLineUserError("--foxglove: '::1:8765' is not [HOST:]PORT");
    }

    @Test
    void aTakenPortIsOneLineNamingIt() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            int port = taken.getLocalPort();
            CliRun.of("bench", "--duration", "1s", "--tasks", "1", "--foxglove", Integer.toString(port))
                    .assertOneLineUserError("--foxglove: cannot serve Foxglove on 127.0.0.1:" + port);
        }
    }

    @Test
    void anUnknownHostIsOneLine() {
        CliRun.of("bench", "--duration", "1s", "--tasks", "1", "--foxglove", "no-such-host.invalid:8765")
                .assertOneLineUserError("--foxglove: cannot resolve 'no-such-host.invalid'");
    }

    @Test
    void aComparisonHasNoSingleMonitorToServe() {
        CliRun.of("bench", "--compare", "--foxglove", "0").assertOneLineUserError("--foxglove");
    }
}
