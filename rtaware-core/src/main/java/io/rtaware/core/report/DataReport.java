package io.rtaware.core.report;

import java.util.List;

/**
 * How one key's data arrived over a run.
 *
 * @param name the key
 * @param producer the producing task
 * @param consumers the consuming tasks
 * @param commits number of commits
 * @param rateHz measured commit rate in Hz of world time
 * @param intervalMs min, mean and max interval between commits in ms
 */
public record DataReport(String name, String producer, List<String> consumers, long commits,
                         double rateHz, Interval intervalMs) {

    /**
     * @param min shortest interval
     * @param mean mean interval
     * @param max longest interval
     */
    public record Interval(double min, double mean, double max) {
    }
}
