package io.rtaware.player.probe;

import io.rtaware.core.time.Durations;
import io.rtaware.player.client.PlayerClient;
import io.rtaware.player.client.PlayerClientOptions;
import io.rtaware.player.client.PlayerCounters;
import io.rtaware.player.client.PlayerStats;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import java.io.IOException;
import java.io.PrintStream;
import java.time.Duration;
import java.util.List;
import java.util.Locale;

/**
 * Connects to a Player server, prints its version, devices and drivers, subscribes to
 * {@code position2d:0} and to {@code laser:0} (or {@code ranger:0} when there is no laser) in
 * PUSH mode with the replace rule, and prints data rates and values once per second for the
 * listening time. Stateless between runs; one {@link #run} at a time per instance (it holds
 * no state, so instances may be shared across threads).
 */
public final class PlayerProbe {

    private final PlayerClientOptions options;

    /** @param options connection timeouts and limits */
    public PlayerProbe(PlayerClientOptions options) {
        this.options = options;
    }

    /** A probe with {@link PlayerClientOptions#defaults()}. */
    public PlayerProbe() {
        this(PlayerClientOptions.defaults());
    }

    private record HostPort(String host, int port) {
    }

    private static HostPort parse(String hostPort) throws PlayerProbeException {
        int colon = hostPort == null ? -1 : hostPort.lastIndexOf(':');
        if (colon <= 0 || colon == hostPort.length() - 1) {
            throw new PlayerProbeException("expected HOST:PORT (e.g. 127.0.0.1:6665), got '" + hostPort + "'", null);
        }
        int port;
        try {
            port = Integer.parseInt(hostPort.substring(colon + 1));
        } catch (NumberFormatException e) {
            throw new PlayerProbeException("port in '" + hostPort + "' is not a number", null);
        }
        if (port < 1 || port > 65535) {
            throw new PlayerProbeException("port " + port + " in '" + hostPort + "' outside 1..65535", null);
        }
        return new HostPort(hostPort.substring(0, colon), port);
    }

    /**
     * Runs the probe.
     *
     * @param hostPort {@code HOST:PORT} of the server
     * @param listen how long to print data
     * @param out where to print
     * @return 0 when data from position2d and the scan source arrived, 1 otherwise (after a line saying
     *     which did not)
     * @throws PlayerProbeException with a one-line message if the address is malformed, the
     *     server is unreachable, is not a Player server, or fails during the probe
     */
    public int run(String hostPort, Duration listen, PrintStream out) throws PlayerProbeException {
        HostPort hp = parse(hostPort);
        String host = hp.host();
        int port = hp.port();
        PlayerCounters counters = new PlayerCounters();
        try (PlayerClient client = PlayerClient.connect(host, port, options, counters)) {
            out.println("Player server " + hostPort + ": version " + client.serverVersion());
            List<DeviceAddress> devices = client.deviceList();
            out.println(devices.size() + " devices:");
            DeviceAddress scan = null;
            boolean hasPosition = false;
            for (DeviceAddress d : devices) {
                out.println("  " + d + " (" + client.driverInfo(d) + ")");
                hasPosition |= d.interf() == Interfaces.POSITION2D && d.index() == 0;
                if (d.interf() == Interfaces.LASER && d.index() == 0) {
                    scan = d;
                } else if (d.interf() == Interfaces.RANGER && d.index() == 0 && scan == null) {
                    scan = d;
                }
            }
            client.setDataMode(Subtypes.DATAMODE_PUSH);
            client.addReplaceRule(ReplaceRule.latestDataOnly());
            if (hasPosition) {
                client.subscribe(DeviceAddress.of(Interfaces.POSITION2D, 0));
                out.println("subscribed position2d:0, geometry " + client.position2dGeometry(0));
            } else {
                out.println("no position2d:0 on this server");
            }
            boolean ranger = scan != null && scan.interf() == Interfaces.RANGER;
            if (scan != null) {
                client.subscribe(DeviceAddress.of(scan.interf(), 0));
                out.println("subscribed " + scan + (ranger ? ", config " + client.rangerConfig(0) : ""));
            } else {
                out.println("no laser:0 or ranger:0 on this server");
            }
            return listen(client, ranger, listen, out, counters);
        } catch (IOException e) {
            throw new PlayerProbeException("player-probe " + hostPort + ": " + e.getMessage(), e);
        }
    }

    private static int listen(PlayerClient client, boolean ranger, Duration listen, PrintStream out,
                              PlayerCounters counters) throws IOException {
        long endMs = System.currentTimeMillis() + listen.toMillis();
        long odo0 = client.odometryUpdates();
        long scan0 = scans(client, ranger);
        while (true) {
            long secondStart = System.currentTimeMillis();
            if (secondStart >= endMs) {
                break;
            }
            long odoBefore = client.odometryUpdates();
            long scanBefore = scans(client, ranger);
            long until = Math.min(endMs, secondStart + 1000);
            while (System.currentTimeMillis() < until) {
                client.poll((int) Math.max(1, until - System.currentTimeMillis()), false);
            }
            double seconds = Math.max(1, System.currentTimeMillis() - secondStart) / 1000.0;
            Odometry o = client.odometry();
            LaserScan s = ranger ? client.rangerScan() : client.laserScan();
            out.println(String.format(Locale.ROOT,
                    "odometry %5.1f Hz pose (%.3f, %.3f, %.3f) vel (%.3f, %.3f) stall %s t=%.2f | scan %5.1f Hz"
                            + " %d beams %.3f..%.3f rad, r[0]=%.3f r[mid]=%.3f max %.2f m",
                    (client.odometryUpdates() - odoBefore) / seconds, o.xM, o.yM, o.yawRad, o.vxMps, o.omegaRadPerSec,
                    o.stall, o.serverTimeS, (scans(client, ranger) - scanBefore) / seconds, s.count(), s.minAngleRad,
                    s.maxAngleRad, s.count() > 0 ? s.rangesM[0] : Float.NaN,
                    s.count() > 0 ? s.rangesM[s.count() / 2] : Float.NaN, s.maxRangeM));
        }
        PlayerStats st = counters.snapshot();
        out.println("received " + st.messagesReceived() + " messages (" + st.bytesReceived() + " bytes), "
                + st.protocolErrors() + " protocol errors, " + st.skippedMessages() + " skipped");
        boolean odometry = client.odometryUpdates() > odo0;
        boolean scan = scans(client, ranger) > scan0;
        if (odometry && scan) {
            return 0;
        }
        String missing = odometry ? "no scan" : scan ? "no odometry" : "no odometry and no scan";
        out.println(missing + " arrived in " + Durations.format(listen.toNanos()) + ": check the server has position2d:0 and laser:0 "
                + "or ranger:0, and that its simulation is running");
        return 1;
    }

    private static long scans(PlayerClient client, boolean ranger) {
        return ranger ? client.rangerUpdates() : client.laserUpdates();
    }
}
