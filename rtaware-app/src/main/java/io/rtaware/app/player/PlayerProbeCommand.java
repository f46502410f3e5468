package io.rtaware.app.player;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.DurationConverter;
import io.rtaware.core.time.Durations;
import io.rtaware.player.probe.PlayerProbe;
import io.rtaware.player.probe.PlayerProbeException;
import java.time.Duration;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code rtaware player-probe HOST:PORT}: the first thing to run against a new robot. Connects,
 * lists the server's devices and drivers, subscribes to position2d and the laser or ranger, and
 * prints a few seconds of data rates and values.
 */
@Command(name = "player-probe", mixinStandardHelpOptions = true,
        description = {"Connect to a Player server, list its devices and drivers, and print data rates and values.",
                "Example: rtaware player-probe 127.0.0.1:6665"})
public final class PlayerProbeCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "HOST:PORT", description = "The Player server, e.g. 127.0.0.1:6665.")
    String hostPort;

    @Option(names = "--listen", converter = DurationConverter.class, defaultValue = "3s", paramLabel = "DURATION",
            description = "How long to print data for (default: ${DEFAULT-VALUE}).")
    long listenNs;

    @Override
    public Integer call() {
        if (listenNs <= 0) {
            throw new UserError("--listen must be positive, got " + Durations.format(listenNs));
        }
        try {
            return new PlayerProbe().run(hostPort, Duration.ofNanos(listenNs), System.out) == 0 ? 0 : 1;
        } catch (PlayerProbeException e) {
            throw new UserError(e.getMessage());
        }
    }
}
