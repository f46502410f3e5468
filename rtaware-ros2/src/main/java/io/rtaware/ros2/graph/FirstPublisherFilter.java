package io.rtaware.ros2.graph;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * Follows one publisher of a topic when several publish on it, telling them apart by the gid of
 * the rmw_zenoh attachment ({@link SampleAttachment}). The first publisher heard is followed; the
 * samples of every other are to be dropped, and each other publisher is reported once. When the
 * followed publisher has been silent for {@code silenceNs} (a driver restarted, with a new gid),
 * the next publisher heard is followed instead, and that is reported too. Samples without an
 * rmw_zenoh attachment name no publisher and are let through.
 *
 * <p>Allocates only when a new publisher is heard (its gid and the report). Not thread-safe: the
 * reader thread owns it; {@link #ignored()} may be read from any thread.
 */
public final class FirstPublisherFilter {

    private final String topic;
    private final long silenceNs;
    private final Consumer<String> report;
    private final byte[] followed = new byte[SampleAttachment.GID_BYTES];
    private final List<byte[]> others = new ArrayList<>();
    private boolean following;
    private long followedLastNs;
    private volatile long ignored;

    /**
     * @param topic the topic's name in reports, e.g. {@code /robot1/odom}
     * @param silenceNs how long the followed publisher may be silent before another is followed
     * @param report receives one line per publisher that is ignored or followed after a silence
     * @throws IllegalArgumentException if {@code silenceNs} is not positive
     */
    public FirstPublisherFilter(String topic, long silenceNs, Consumer<String> report) {
        this.topic = Objects.requireNonNull(topic, "topic");
        this.report = Objects.requireNonNull(report, "report");
        if (silenceNs <= 0) {
            throw new IllegalArgumentException("silenceNs must be positive, got " + silenceNs);
        }
        this.silenceNs = silenceNs;
    }

    /**
     * @param attachment the received sample's attachment memory
     * @param attachmentLength its length (-1 when the sample had none)
     * @param nowNs the receiver's time now (any monotonic clock, the same on every call)
     * @return true if the sample is to be used: it comes from the followed publisher or names none
     */
    public boolean accept(ByteBuffer attachment, int attachmentLength, long nowNs) {
        if (!SampleAttachment.valid(attachment, attachmentLength)) {
            return true;
        }
        if (!following || (!isFollowed(attachment) && nowNs - followedLastNs >= silenceNs)) {
            if (following) {
                report.accept(String.format(Locale.ROOT, "%s: publisher %s silent for %.1f s; following publisher %s",
                        topic, hex(followed), (nowNs - followedLastNs) / 1e9, hex(gidOf(attachment))));
            }
            attachment.get(SampleAttachment.GID_OFFSET, followed);
            following = true;
            others.removeIf(this::sameAsFollowed);
        }
        if (isFollowed(attachment)) {
            followedLastNs = nowNs;
            return true;
        }
        ignored++;
        if (!known(attachment)) {
            byte[] gid = gidOf(attachment);
            others.add(gid);
            report.accept(String.format(Locale.ROOT, "%s: another publisher (%s) besides the one followed (%s); "
                    + "its samples are dropped", topic, hex(gid), hex(followed)));
        }
        return false;
    }

    /** @return samples dropped because another publisher than the followed one sent them */
    public long ignored() {
        return ignored;
    }

    private boolean known(ByteBuffer attachment) {
        for (int i = 0; i < others.size(); i++) {
            if (matches(attachment, others.get(i))) {
                return true;
            }
        }
        return false;
    }

    private boolean isFollowed(ByteBuffer attachment) {
        return matches(attachment, followed);
    }

    private boolean sameAsFollowed(byte[] gid) {
        return Arrays.equals(gid, followed);
    }

    private static boolean matches(ByteBuffer attachment, byte[] gid) {
        for (int i = 0; i < SampleAttachment.GID_BYTES; i++) {
            if (attachment.get(SampleAttachment.GID_OFFSET + i) != gid[i]) {
                return false;
            }
        }
        return true;
    }

    private static byte[] gidOf(ByteBuffer attachment) {
        byte[] gid = new byte[SampleAttachment.GID_BYTES];
        attachment.get(SampleAttachment.GID_OFFSET, gid);
        return gid;
    }

    private static String hex(byte[] gid) {
        return "gid " + HexFormat.of().formatHex(gid);
    }
}
