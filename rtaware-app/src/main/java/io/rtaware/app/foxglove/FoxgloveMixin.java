package io.rtaware.app.foxglove;

import io.rtaware.app.UserError;
import io.rtaware.foxglove.FoxgloveAddress;
import io.rtaware.foxglove.FoxgloveAddressException;
import io.rtaware.foxglove.FoxgloveServer;
import java.io.PrintStream;
import picocli.CommandLine.Option;

/**
 * {@code --foxglove [HOST:]PORT}, shared by {@code run}, {@code bench} and {@code sim} (a picocli
 * mixin): serves the command live to Foxglove over its WebSocket protocol, the channels a
 * recording would hold. Without the flag nothing is started. Not thread-safe (picocli fills it).
 */
public final class FoxgloveMixin {

    /** The section of report.json with what the server did. */
    public static final String SECTION = "foxglove";

    @Option(names = "--foxglove", paramLabel = "[HOST:]PORT",
            description = "Serve it live to Foxglove (Open connection, Foxglove WebSocket) on PORT of 127.0.0.1, or on "
                    + "HOST:PORT (0.0.0.0:PORT exposes it to other machines, deliberately); 0 takes a free port. "
                    + "Prints 'foxglove: ws://HOST:PORT'. The channels of a recording, the timing channels beside the "
                    + "robot's; at most " + FoxgloveServer.DEFAULT_MAX_CLIENTS + " clients, a slow one loses messages "
                    + "(counted in report.json), never slows a task.")
    String address;

    /** @return true if {@code --foxglove} was given */
    public boolean enabled() {
        return address != null;
    }

    /**
     * Checks the value before anything runs.
     *
     * @return the address, or null without the flag
     * @throws UserError if it is not {@code [HOST:]PORT}
     */
    public FoxgloveAddress address() {
        if (address == null) {
            return null;
        }
        try {
            return FoxgloveAddress.parse(address);
        } catch (IllegalArgumentException e) {
            throw new UserError("--foxglove: " + e.getMessage());
        }
    }

    /**
     * Starts the server, if {@code --foxglove} was given, and prints its URL; where it listens on
     * more than loopback, says so on that line and warns on {@code err}.
     *
     * @param command the command's name, in the server's name ({@code rtaware run})
     * @param out where the {@code foxglove: URL} line goes
     * @param err where the warning of an exposed server goes
     * @return the server (close it when the command ends), or null without the flag
     * @throws UserError if the value is bad, the host does not resolve or the port is taken
     */
    public FoxgloveServer start(String command, PrintStream out, PrintStream err) {
        FoxgloveAddress where = address();
        if (where == null) {
            return null;
        }
        FoxgloveServer server;
        try {
            server = FoxgloveServer.start(where, "rtaware " + command);
        } catch (FoxgloveAddressException e) {
            throw new UserError("--foxglove: " + e.getMessage());
        }
        if (server.exposed()) {
            out.println("foxglove: " + server.url() + " on this machine; listening on " + server.listening()
                    + ", reachable from other machines (in Foxglove: Open connection, Foxglove WebSocket)");
            err.println("warning: --foxglove listens on " + server.listening() + ": anyone who can reach this machine "
                    + "sees the run (the protocol has no authentication); a bare PORT keeps it on this machine");
            err.flush();
        } else {
            out.println("foxglove: " + server.url() + " (in Foxglove: Open connection, Foxglove WebSocket)");
        }
        out.flush();
        return server;
    }

    /**
     * Closes a server; nothing without one.
     *
     * @param server what {@link #start} returned, or null
     */
    public static void close(FoxgloveServer server) {
        if (server != null) {
            server.close();
        }
    }
}
