package glint.scenefile;

import java.util.HashSet;
import java.util.Set;
import org.snakeyaml.engine.v2.common.Anchor;
import org.snakeyaml.engine.v2.events.AliasEvent;
import org.snakeyaml.engine.v2.events.CollectionStartEvent;
import org.snakeyaml.engine.v2.events.Event;
import org.snakeyaml.engine.v2.events.ScalarEvent;
import org.snakeyaml.engine.v2.exceptions.Mark;
import org.snakeyaml.engine.v2.parser.Parser;

/**
 * Hands the YAML parser's events on to the composer and stops at the first alias of a list or
 * mapping beyond the most allowed, with where it stands: the composer counts them as well (an alias
 * bomb's copies grow exponentially), but says only that there are too many.
 */
final class AliasCountingParser extends CheckingParser {

    /** The first alias too many, with where it stands; thrown through the composer. */
    static final class TooManyAliases extends RuntimeException {
        final int line;
        final int column;

        TooManyAliases(int line, int column) {
            super("too many aliases", null, false, false);
            this.line = line;
            this.column = column;
        }
    }

    private final int most;
    /** The anchors that name a list or a mapping (as last defined). */
    private final Set<Anchor> collections = new HashSet<>();
    private int aliases;

    AliasCountingParser(Parser parser, int most) {
        super(parser);
        this.most = most;
    }

    @Override
    void check(Event event) {
        if (event instanceof CollectionStartEvent c) {
            c.getAnchor().ifPresent(collections::add);
        } else if (event instanceof ScalarEvent s) {
            s.getAnchor().ifPresent(collections::remove);
        } else if (event instanceof AliasEvent a && collections.contains(a.getAlias()) && ++aliases > most) {
            Mark mark = a.getStartMark().orElse(null);
            throw mark == null ? new TooManyAliases(0, 0) : new TooManyAliases(mark.getLine() + 1, mark.getColumn() + 1);
        }
    }
}
