package io.rtaware.core.monitor;

import java.util.List;

/**
 * The task set cannot run: every violation found while verifying it, each a sentence naming the
 * task, the key and what exists instead. Thrown before anything runs.
 */
public final class ConfigurationException extends RuntimeException {

    /** Every violation found, in the order found. */
    private final List<String> violations;

    /** @param violations every problem found, at least one */
    public ConfigurationException(List<String> violations) {
        super(violations.size() == 1 ? violations.get(0)
                : violations.size() + " configuration errors:\n  " + String.join("\n  ", violations));
        this.violations = List.copyOf(violations);
    }

    /** @return every violation, in the order found */
    public List<String> violations() {
        return violations;
    }
}
