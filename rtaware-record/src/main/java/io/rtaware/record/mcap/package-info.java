/**
 * MCAP (https://mcap.dev/spec), the log format of ROS 2 bags and Foxglove: a writer producing
 * indexed, chunked files with a summary (schemas, channels, statistics, chunk indexes, summary
 * offsets) and CRCs, and a reader that checks those CRCs and hands every record to a visitor.
 * Chunks are compressed with zstd through zstd-jni, or left uncompressed.
 */
package io.rtaware.record.mcap;
