package io.rtaware.app.live;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.DurationConverter;
import io.rtaware.live.LiveOptions;
import java.net.InetAddress;
import java.net.UnknownHostException;
import picocli.CommandLine.Option;

/** The {@code --live} options shared by {@code run} and {@code bench}. Not thread-safe (picocli fills it). */
public final class LiveMixin {

    @Option(names = "--live", description = "Serve a live view in a browser while it runs (tasks, keys and, for run, "
            + "the map); prints 'live view: URL'. Loopback only unless --live-bind says otherwise.")
    boolean live;

    @Option(names = "--live-port", paramLabel = "P", defaultValue = "0",
            description = "Port of the live view (default: a free port).")
    int port;

    @Option(names = "--live-bind", paramLabel = "ADDR", defaultValue = LiveOptions.LOOPBACK,
            description = "Address the live view listens on (default: ${DEFAULT-VALUE}; 0.0.0.0 exposes it to "
                    + "other machines, deliberately).")
    String bind;

    @Option(names = "--live-linger", paramLabel = "DURATION", converter = DurationConverter.class, defaultValue = "5s",
            description = "Keep serving the final page this long after the run has ended, e.g. 30s "
                    + "(default: ${DEFAULT-VALUE}; Ctrl-C ends it sooner).")
    long lingerNs;

    /**
     * @return the validated options
     * @throws UserError for a bad port or linger time, or a bind address that does not resolve
     */
    public LiveOptions options() {
        LiveOptions options;
        try {
            options = new LiveOptions(live, bind, port, lingerNs);
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        if (live) {
            try {
                InetAddress.getByName(bind);
            } catch (UnknownHostException e) {
                throw new UserError("--live-bind: cannot resolve '" + bind + "' to an address of this machine");
            }
        }
        return options;
    }
}
