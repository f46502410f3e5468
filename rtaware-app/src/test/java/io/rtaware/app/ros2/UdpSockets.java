package io.rtaware.app.ros2;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * The local addresses of the UDP sockets some processes hold, read from Linux's {@code /proc}: a
 * process's socket inodes from {@code /proc/PID/fd}, their addresses from {@code /proc/net/udp}
 * and {@code /proc/net/udp6}. What {@code ss -uanp} shows, without needing {@code ss}.
 */
final class UdpSockets {

    private UdpSockets() {
    }

    /**
     * @param processes the processes (still running)
     * @return each of their UDP sockets' local address as {@code 127.0.0.1:7410} or {@code [::]:7410}
     * @throws IOException if {@code /proc} cannot be read
     */
    static List<String> localAddresses(List<ProcessHandle> processes) throws IOException {
        Set<String> inodes = new HashSet<>();
        for (ProcessHandle p : processes) {
            try (DirectoryStream<Path> fds = Files.newDirectoryStream(Path.of("/proc", Long.toString(p.pid()), "fd"))) {
                for (Path fd : fds) {
                    String target = readLink(fd);
                    if (target != null && target.startsWith("socket:[")) {
                        inodes.add(target.substring("socket:[".length(), target.length() - 1));
                    }
                }
            }
        }
        List<String> addresses = new ArrayList<>();
        for (String table : List.of("/proc/net/udp", "/proc/net/udp6")) {
            Path file = Path.of(table);
            if (!Files.isReadable(file)) {
                continue;
            }
            for (String line : Files.readAllLines(file)) {
                String[] f = line.trim().split("\\s+");
                if (f.length > 9 && f[1].contains(":") && inodes.contains(f[9])) {
                    addresses.add(address(f[1]));
                }
            }
        }
        return addresses;
    }

    private static String readLink(Path fd) {
        try {
            return Files.readSymbolicLink(fd).toString();
        } catch (IOException e) {
            return null; // closed since the listing
        }
    }

    /** {@code 0100007F:1CF2} (IPv4, bytes in host order, little-endian here) or 32 hex digits (IPv6). */
    static String address(String hex) {
        int colon = hex.indexOf(':');
        String ip = hex.substring(0, colon);
        int port = Integer.parseInt(hex.substring(colon + 1), 16);
        if (ip.length() == 8) {
            long v = Long.parseLong(ip, 16);
            return String.format(Locale.ROOT, "%d.%d.%d.%d:%d", v & 0xff, (v >> 8) & 0xff, (v >> 16) & 0xff, (v >> 24) & 0xff,
                    port);
        }
        StringBuilder v6 = new StringBuilder("[");
        for (int word = 0; word < 4; word++) {
            long w = Long.parseLong(ip.substring(word * 8, word * 8 + 8), 16);
            long be = Long.reverseBytes(w) >>> 32;
            v6.append(word == 0 ? "" : ":").append(String.format(Locale.ROOT, "%x:%x", be >>> 16, be & 0xffff));
        }
        return v6.append("]:").append(port).toString();
    }
}
