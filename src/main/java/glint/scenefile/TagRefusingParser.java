package glint.scenefile;

import java.util.Optional;
import org.snakeyaml.engine.v2.events.CollectionStartEvent;
import org.snakeyaml.engine.v2.events.Event;
import org.snakeyaml.engine.v2.events.ScalarEvent;
import org.snakeyaml.engine.v2.exceptions.Mark;
import org.snakeyaml.engine.v2.parser.Parser;

/**
 * Hands the YAML parser's events on to the composer and stops at the first explicit tag
 * ({@code !!str 1}, {@code !foo x}): a scene has no use for tags, and silently ignoring one would
 * make {@code radius: !!str 1} a number though {@code radius: "1"} is refused.
 */
final class TagRefusingParser extends CheckingParser {

    /** The first tag, with where it stands; thrown through the composer. */
    static final class TagFound extends RuntimeException {
        final String tag;
        final int line;
        final int column;

        TagFound(String tag, int line, int column) {
            super(tag, null, false, false);
            this.tag = tag;
            this.line = line;
            this.column = column;
        }
    }

    private static final String CORE_PREFIX = "tag:yaml.org,2002:";

    TagRefusingParser(Parser parser) {
        super(parser);
    }

    @Override
    void check(Event event) {
        Optional<String> tag = event instanceof ScalarEvent s ? s.getTag()
                : event instanceof CollectionStartEvent c ? c.getTag() : Optional.empty();
        if (tag.isPresent()) {
            String written = tag.get().startsWith(CORE_PREFIX)
                    ? "!!" + tag.get().substring(CORE_PREFIX.length()) : tag.get();
            Mark mark = event.getStartMark().orElse(null);
            throw mark == null ? new TagFound(written, 0, 0)
                    : new TagFound(written, mark.getLine() + 1, mark.getColumn() + 1);
        }
    }
}
