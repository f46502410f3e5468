package io.rtaware.record.mcap;

import java.util.List;

/**
 * What a file's summary section says.
 *
 * @param profile the header's profile
 * @param schemas schema records
 * @param channels channel records
 * @param statistics the statistics record
 * @param chunkIndexCount chunk index records
 */
public record McapSummary(String profile, List<McapSchema> schemas, List<McapChannel> channels,
                          McapStatistics statistics, int chunkIndexCount) {
}
