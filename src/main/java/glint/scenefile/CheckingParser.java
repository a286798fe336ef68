package glint.scenefile;

import org.snakeyaml.engine.v2.events.Event;
import org.snakeyaml.engine.v2.parser.Parser;

/**
 * A YAML parser that hands another one's events on to the composer, each checked first by
 * {@link #check}, which may stop the reading by throwing.
 */
abstract class CheckingParser implements Parser {

    private final Parser parser;

    CheckingParser(Parser parser) {
        this.parser = parser;
    }

    /** Looks at the next event before the composer takes it. */
    abstract void check(Event event);

    @Override
    public final boolean checkEvent(Event.ID id) {
        return parser.checkEvent(id);
    }

    @Override
    public final Event peekEvent() {
        return parser.peekEvent();
    }

    @Override
    public final boolean hasNext() {
        return parser.hasNext();
    }

    @Override
    public final Event next() {
        Event event = parser.next();
        check(event);
        return event;
    }
}
