package glint.app;

import glint.config.JarCommand;
import glint.ui.input.KeyBindings;
import java.util.ArrayList;
import java.util.List;

/** The end of {@code --help}: a few example commands and the window's keys (from {@link KeyBindings}). */
final class HelpFooter {

    private HelpFooter() {
    }

    /** The footer's lines. */
    static List<String> lines() {
        String jar = JarCommand.java();
        List<String> lines = new ArrayList<>();
        lines.add("");
        lines.add("Examples:");
        lines.add("  Open the window on the config's scene, or on another one:");
        lines.add("    " + jar);
        lines.add("    " + jar + " --scene scenes/glass.yaml");
        lines.add("  Render a still to a file, or one of the scene's views; time 10 frames:");
        lines.add("    " + jar + " --scene scenes/metals.yaml --output metals.png");
        lines.add("    " + jar + " --scene scenes/field.yaml --view 2 --output a.png");
        lines.add("    " + jar + " --scene scenes/field.yaml --bench 10");
        lines.add("  Light that bounces (the path integrator), 64 samples a pixel:");
        lines.add("    " + jar + " --integrator path --spp 64 --output bounce.png");
        lines.add("  Settings rank: a flag, then the scene's render: block, then the config.");
        lines.add("");
        lines.add("Window keys (Enter renders the view as a still; the window goes on):");
        for (String help : KeyBindings.helpLines()) {
            lines.add("  " + help);
        }
        return lines;
    }

    /** The footer as picocli takes it: every line ends in %n, and a '%' of the text is doubled. */
    static String text() {
        StringBuilder sb = new StringBuilder();
        for (String line : lines()) {
            sb.append(line.replace("%", "%%")).append("%n");
        }
        return sb.toString();
    }
}
