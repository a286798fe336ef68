package glint.ui.scenes;

import glint.config.Config;
import glint.input.InputException;

/** Reads the config again (F5), with the command line's overrides applied as at start. */
@FunctionalInterface
public interface ConfigSource {

    Config load() throws InputException;
}
