package glint.app;

import glint.input.InputException;
import glint.input.Suggestions;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * The arguments the parser did not know, in words: each mistyped option with the known one closest to
 * it ({@code unknown option '--sppp'; did you mean '--spp'?}), the value after it left out (it is the
 * option's, not an option of its own), and any other word that stands where no argument goes.
 */
final class UnknownArguments {

    private UnknownArguments() {
    }

    /** One line for each unknown option or stray word of {@code unmatched}, in order. */
    static List<String> lines(List<String> unmatched, CommandSpec spec) {
        List<String> names = longNames(spec);
        List<String> lines = new ArrayList<>();
        boolean afterUnknownOption = false;
        for (String arg : unmatched) {
            if (isOption(arg)) {
                String name = arg.contains("=") ? arg.substring(0, arg.indexOf('=')) : arg;
                String known = Suggestions.closest(name, names);
                lines.add("unknown option " + InputException.quote(name)
                        + (known != null ? "; did you mean '" + known + "'?" : ""));
                afterUnknownOption = !arg.contains("=");
            } else if (afterUnknownOption) {
                afterUnknownOption = false; // the value the unknown option was given
            } else {
                lines.add("unexpected argument " + InputException.quote(arg) + (isSceneFile(arg)
                        ? "; did you mean '--scene " + InputException.cutPath(arg) + "'?"
                        : " (each value follows its option, as in --spp 4)"));
            }
        }
        return lines;
    }

    /** A word that is written as an option: a dash, then not a number (the value -5 is not an option). */
    private static boolean isOption(String arg) {
        return arg.length() > 1 && arg.charAt(0) == '-' && !arg.matches("-[0-9.]+");
    }

    private static boolean isSceneFile(String arg) {
        return arg.endsWith(".yaml") || arg.endsWith(".yml");
    }

    /** The options' long names ({@code --scene}, ..., {@code --help}, {@code --version}). */
    private static List<String> longNames(CommandSpec spec) {
        List<String> names = new ArrayList<>();
        for (OptionSpec option : spec.options()) {
            names.add(option.longestName());
        }
        return names;
    }
}
