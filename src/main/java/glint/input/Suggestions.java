package glint.input;

import java.util.Collection;
import java.util.Locale;

/** "Did you mean" hints: the known word closest to a misspelt one. */
public final class Suggestions {

    private Suggestions() {
    }

    /**
     * A hint for {@code given} among {@code known}: {@code " (did you mean 'x'?)"} when one is close
     * enough to be a typo, otherwise {@code " (expected one of: a, b, c)"}.
     */
    public static String hint(String given, Collection<String> known) {
        String best = closest(given, known);
        if (best != null) {
            return " (did you mean '" + best + "'?)";
        }
        return " (expected one of: " + String.join(", ", known) + ")";
    }

    /**
     * The known word closest to {@code given} (ignoring case) when it is close enough to be a typo of it:
     * at most 2 edits away, or a third of the word's length; otherwise null.
     */
    public static String closest(String given, Collection<String> known) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String candidate : given.length() > 64 ? java.util.List.<String>of() : known) {
            int d = distance(given.toLowerCase(Locale.ROOT), candidate.toLowerCase(Locale.ROOT));
            if (d < bestDistance) {
                bestDistance = d;
                best = candidate;
            }
        }
        return best != null && bestDistance <= Math.max(2, best.length() / 3) ? best : null;
    }

    /** The Levenshtein edit distance (insertions, deletions, substitutions). */
    static int distance(String a, String b) {
        int[] previous = new int[b.length() + 1];
        int[] current = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int substitution = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(substitution, Math.min(previous[j], current[j - 1]) + 1);
            }
            int[] swap = previous;
            previous = current;
            current = swap;
        }
        return previous[b.length()];
    }
}
