package io.rtaware.experiment.claims;

import com.fasterxml.jackson.annotation.JsonValue;
import java.util.Locale;

/** A verdict on a claim of the paper. */
public enum Verdict {
    /** The results show what the paper claims. */
    REPRODUCED,
    /** The results do not show it. */
    NOT_REPRODUCED,
    /** The results show it in part. */
    MIXED,
    /** The results show no difference, but the test could not have detected the paper's difference. */
    INCONCLUSIVE,
    /** The setup cannot reproduce the claim's mechanism (the evidence says why). */
    NOT_COMPARABLE;

    /**
     * @return the name in {@code summary.json}: {@code reproduced}, {@code not_reproduced},
     *     {@code mixed}, {@code inconclusive} or {@code not_comparable}
     */
    @JsonValue
    public String json() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * @param agree how many parts of a claim agree with the paper
     * @param of how many parts were judged, at least 1
     * @return reproduced if all agree, not reproduced if none does, mixed otherwise
     */
    public static Verdict ofParts(int agree, int of) {
        return agree == of ? REPRODUCED : agree == 0 ? NOT_REPRODUCED : MIXED;
    }
}
