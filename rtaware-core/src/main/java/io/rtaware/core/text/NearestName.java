package io.rtaware.core.text;

import java.util.Collection;
import java.util.Locale;
import java.util.Optional;

/**
 * The known name nearest to a mistyped one, by edit distance (insertions, deletions,
 * substitutions and swaps of two neighbouring letters each cost one; case is ignored), for a
 * message such as {@code unknown scenario 'ofice'; did you mean 'office'?}. A name is suggested
 * only when it is close: at most one edit for names of up to four letters, else at most a third of
 * the typed length. Stateless.
 */
public final class NearestName {

    private NearestName() {
    }

    /**
     * @param typed what the user gave
     * @param known the names that exist
     * @return the nearest known name, if one is close enough to be what was meant (the first of
     *     equally near ones, in the collection's order)
     */
    public static Optional<String> of(String typed, Collection<String> known) {
        String t = typed.toLowerCase(Locale.ROOT);
        int limit = Math.max(1, t.length() / 3);
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String name : known) {
            int d = distance(t, name.toLowerCase(Locale.ROOT));
            if (d < bestDistance) {
                best = name;
                bestDistance = d;
            }
        }
        return best != null && bestDistance > 0 && bestDistance <= limit ? Optional.of(best) : Optional.empty();
    }

    /**
     * @param typed what the user gave
     * @param known the names that exist
     * @return {@code "; did you mean 'NAME'?"} for the nearest name, or the empty string
     */
    public static String suggestion(String typed, Collection<String> known) {
        return of(typed, known).map(n -> "; did you mean '" + n + "'?").orElse("");
    }

    /** Optimal string alignment distance: Levenshtein with swaps of neighbouring letters. */
    static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= b.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                int v = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    v = Math.min(v, d[i - 2][j - 2] + 1);
                }
                d[i][j] = v;
            }
        }
        return d[a.length()][b.length()];
    }
}
