package io.rtaware.core.data;

/**
 * How a key's data actually arrived: commit count and the intervals between commits, in
 * world time.
 *
 * @param commits number of commits
 * @param firstCommitNs world time of the first commit (0 if none)
 * @param lastCommitNs world time of the last commit (0 if none)
 * @param minIntervalNs shortest interval between consecutive commits (0 if fewer than two)
 * @param maxIntervalNs longest interval between consecutive commits (0 if fewer than two)
 */
public record FeedStats(long commits, long firstCommitNs, long lastCommitNs,
                        long minIntervalNs, long maxIntervalNs) {

    /**
     * @return mean interval between consecutive commits in ns, or 0 with fewer than two commits
     */
    public double meanIntervalNs() {
        return commits < 2 ? 0.0 : (double) (lastCommitNs - firstCommitNs) / (commits - 1);
    }

    /**
     * The measured arrival rate: commits after the first, over the time from first to last
     * commit. A feed that committed fewer than twice has rate 0.
     *
     * @return rate in Hz of world time
     */
    public double rateHz() {
        double mean = meanIntervalNs();
        return mean <= 0 ? 0.0 : 1e9 / mean;
    }
}
