package io.rtaware.record;

/**
 * What a recording holds: the {@code recording} section of a run's report.
 *
 * @param file the MCAP file, or null for a recording made for a {@link RecordingTap} alone
 * @param messages messages written
 * @param bytes the file's size in bytes
 * @param dropped records dropped because the writer fell behind (its rings were full)
 * @param outOfOrder messages written after one with a later log time (they arrived after the
 *     reorder window had passed them)
 * @param error why the file could not be completed, or null
 */
public record RecordingStats(String file, long messages, long bytes, long dropped, long outOfOrder, String error) {
}
