package glint.scenefile;

import glint.input.InputException;
import java.util.ArrayList;
import java.util.List;

/**
 * The names of a scene's views as they are read: each non-empty and its own, counting the default
 * names ({@code view 2} for the second view without one) with those written.
 */
final class ViewNames {

    private final List<String> names = new ArrayList<>();
    private final List<Boolean> written = new ArrayList<>();

    /** The default name of the next view: {@code view N}. */
    String nextDefault() {
        return "view " + (names.size() + 1);
    }

    /** Why the next view cannot have the name written for it, or null when it can. */
    String problemWithWritten(String name) {
        String what = nextDefault();
        if (name.isBlank()) {
            return "the name of " + what + " is empty; expected a name such as 'front', or no name for '" + what + "'";
        }
        int earlier = names.indexOf(name);
        if (earlier < 0) {
            return null;
        }
        return "duplicate view name " + InputException.quote(name) + ", already the "
                + (written.get(earlier) ? "name" : "default name") + " of view " + (earlier + 1)
                + "; each view needs a name of its own";
    }

    /** Why the next view cannot go without a name (its default one is taken), or null when it can. */
    String problemWithDefault() {
        String what = nextDefault();
        int earlier = names.indexOf(what);
        return earlier < 0 ? null : what + " has no name, and its default name '" + what
                + "' is already the name of view " + (earlier + 1) + "; give " + what + " a name of its own";
    }

    void add(String name, boolean wasWritten) {
        names.add(name);
        written.add(wasWritten);
    }
}
