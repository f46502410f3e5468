package io.rtaware.record.mcap;

import java.util.Map;

/**
 * The statistics record of a summary.
 *
 * @param messageCount messages in the file
 * @param schemaCount schemas
 * @param channelCount channels
 * @param metadataCount metadata records
 * @param chunkCount chunks
 * @param messageStartNs earliest log time
 * @param messageEndNs latest log time
 * @param channelMessageCounts messages per channel id
 */
public record McapStatistics(long messageCount, int schemaCount, long channelCount, long metadataCount,
                             long chunkCount, long messageStartNs, long messageEndNs,
                             Map<Integer, Long> channelMessageCounts) {
}
