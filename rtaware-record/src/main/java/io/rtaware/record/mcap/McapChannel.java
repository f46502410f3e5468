package io.rtaware.record.mcap;

import java.util.Map;

/**
 * A channel record.
 *
 * @param id channel id
 * @param schemaId the schema's id (0: none)
 * @param topic e.g. {@code /scan}
 * @param messageEncoding e.g. {@code cdr}
 * @param metadata key/value pairs
 */
public record McapChannel(int id, int schemaId, String topic, String messageEncoding, Map<String, String> metadata) {
}
