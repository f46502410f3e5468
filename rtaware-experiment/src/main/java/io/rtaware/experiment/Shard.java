package io.rtaware.experiment;

/**
 * One share of an experiment's runs, so that one plan can be split across machines: shard
 * {@code index} of {@code count} makes run {@code j} of set {@code i} (both from 1) when
 * {@code ((i - 1) + (j - 1)) mod count == index - 1}. The shares rotate along the diagonal of
 * the set x run table, so each set's runs are spread evenly over the shards (a slower machine
 * does not slow down one set more than another) and every run of the plan is in exactly one
 * shard. Seeds do not depend on the shard: run j uses the plan's seed + j - 1 wherever it runs.
 *
 * @param index this shard, from 1
 * @param count the number of shards, at least 1
 */
public record Shard(int index, int count) {

    /** The whole plan in one shard. */
    public static final Shard WHOLE = new Shard(1, 1);

    /**
     * Validates the fields.
     *
     * @param index this shard, from 1
     * @param count the number of shards, at least 1
     */
    public Shard {
        if (count < 1 || index < 1 || index > count) {
            throw new IllegalArgumentException("a shard is K/N with 1 <= K <= N, got " + index + "/" + count);
        }
    }

    /**
     * @param text {@code K/N}, e.g. {@code 2/4}
     * @return the shard
     * @throws ExperimentInputException if the text is not of that form
     */
    public static Shard parse(String text) {
        String[] parts = text.strip().split("/", -1);
        try {
            if (parts.length == 2) {
                return new Shard(Integer.parseInt(parts[0].strip()), Integer.parseInt(parts[1].strip()));
            }
        } catch (IllegalArgumentException e) {
            // reported below
        }
        throw new ExperimentInputException("--shard must be K/N with 1 <= K <= N (e.g. 2/4), got '" + text + "'");
    }

    /**
     * @param set a set's number, from 1
     * @param run a run's number, from 1
     * @return true if this shard makes that run
     */
    public boolean includes(int set, int run) {
        return ((set - 1) + (run - 1)) % count == index - 1;
    }

    /** @return true if this shard is the whole plan */
    public boolean whole() {
        return count == 1;
    }

    @Override
    public String toString() {
        return index + "/" + count;
    }
}
