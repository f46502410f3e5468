package io.rtaware.core.analysis;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * What the advice says about a task beside its period: {@code mostly_stale} (the runs it could
 * save) or {@code released_together} (offsets to spread). Serialized in snake_case. Immutable.
 *
 * @param rule the rule that made the note
 * @param evidence the figures, by snake_case name with a unit suffix
 * @param message one sentence a person reads
 */
public record AdviceNote(String rule, Map<String, Object> evidence, String message) {

    /**
     * Copies the evidence so the note stays immutable.
     *
     * @param rule the rule that made the note
     * @param evidence the figures
     * @param message one sentence a person reads
     */
    public AdviceNote {
        evidence = Collections.unmodifiableMap(new LinkedHashMap<>(evidence));
    }
}
