package io.rtaware.robotrun;

/**
 * A span of a run without ground truth (a lost or restarted server), in the {@code run}
 * section's {@code ground_truth_gaps}. Immutable and thread-safe.
 *
 * @param fromS world seconds since the start of the last sample before the gap
 * @param toS world seconds of the first sample after it, or of the end of the run if none came
 * @param open true if no sample came after it before the run ended (the final pose is stale)
 */
public record GroundTruthGap(double fromS, double toS, boolean open) {
}
