package io.rtaware.experiment.claims;

import java.util.ArrayList;
import java.util.List;

/** The caveats of a verdict in words, for the report and RESULTS.md. */
final class Caveats {

    private Caveats() {
    }

    static String of(boolean fragile, String verdictAllRuns, boolean smallSample, Integer fewestRunsPerCell) {
        List<String> parts = new ArrayList<>();
        if (fragile) {
            parts.add("fragile: on all runs, busy ones included, " + verdictAllRuns.replace('_', ' '));
        }
        if (smallSample) {
            parts.add("from fewer than " + PaperClaims.SMALL_SAMPLE_RUNS + " runs per cell (fewest " + fewestRunsPerCell
                    + ")");
        }
        return String.join("; ", parts);
    }
}
