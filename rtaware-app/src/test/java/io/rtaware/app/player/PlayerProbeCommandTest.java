package io.rtaware.app.player;

import io.rtaware.app.CliRun;
import org.junit.jupiter.api.Test;

/** Every input error of {@code player-probe} is one line and exit status 2. */
class PlayerProbeCommandTest {

    @Test
    void listenWithoutAUnitIsOneLineWithStatus2() {
        // it listened 3 ms and exited 1 with no message
        CliRun.of("player-probe", "127.0.0.1:6665", "--listen", "3").assertOneLineUserError("'3' has no unit");
    }

    @Test
    void listenOfZeroIsOneLineWithStatus2() {
        CliRun.of("player-probe", "127.0.0.1:6665", "--listen", "0").assertOneLineUserError("--listen must be positive, got 0ns");
    }

    @Test
    void malformedAddressIsOneLineWithStatus2() {
        CliRun.of("player-probe", "localhost").assertOneLineUserError("expected HOST:PORT (e.g. 127.0.0.1:6665), got 'localhost'");
        CliRun.of("player-probe", "localhost:port").assertOneLineUserError("port in 'localhost:port' is not a number");
        CliRun.of("player-probe", "localhost:70000").assertOneLineUserError("port 70000 in 'localhost:70000' outside 1..65535");
    }

    @Test
    void missingAddressIsOneLineWithStatus2() {
        CliRun.of("player-probe").assertOneLineUserError("HOST:PORT");
    }

    @Test
    void serverNotListeningIsOneLineWithStatus2() {
        // port 1 on loopback: nothing listens there on a test machine
        CliRun.of("player-probe", "127.0.0.1:1", "--listen", "1s").assertOneLineUserError("player-probe 127.0.0.1:1: ");
    }
}
