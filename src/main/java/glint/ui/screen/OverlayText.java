package glint.ui.screen;

import glint.render.LightTransport;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.ToIntFunction;

/** The overlay's lines for a frame's stats (key H shows and hides it). */
public final class OverlayText {

    /** A line of the overlay; {@code tone} picks its colour. */
    public record Line(String text, Tone tone) {
    }

    public enum Tone { NORMAL, NOTE, ERROR }

    private OverlayText() {
    }

    public static List<Line> lines(FrameStats s) {
        List<Line> lines = new ArrayList<>();
        if (Double.isNaN(s.fps())) {
            // no rate yet (the first frames after a pause) is not idle: the refinement goes on
            lines.add(normal(String.format(Locale.ROOT, "%s   last frame %.1f ms", s.refined() ? s.converged() ? "idle: converged" : "idle: image complete"
                    : s.renderError().isEmpty() ? "refining" : "waiting to try again", s.msPerFrame())));
        } else {
            lines.add(normal(String.format(Locale.ROOT, "%.1f fps   %.1f ms/frame", s.fps(), s.msPerFrame())));
        }
        String scale = s.renderWidth() == s.viewWidth() ? "full" : String.format(Locale.ROOT, "1/%.2f",
                (double) s.viewWidth() / Math.max(1, s.renderWidth()));
        lines.add(normal(String.format(Locale.ROOT, "render %dx%d (%s of %dx%d)%s", s.renderWidth(),
                s.renderHeight(), scale, s.viewWidth(), s.viewHeight(), s.moving() ? "  moving" : "")));
        if (!s.sizeLimit().isEmpty()) {
            lines.add(new Line("window too large: rendered at most " + s.sizeLimit(), Tone.NOTE));
        }
        if (s.transport().physical()) {
            lines.add(normal(String.format(Locale.ROOT, "samples %d%s%s   threads %d", s.samplesDone(),
                    Double.isNaN(s.noise()) ? "" : String.format(Locale.ROOT, "   noise %.1f %%", 100 * s.noise()),
                    s.converged() ? "   converged" : s.refined() ? "   at most " + s.samplesTotal() : "",
                    s.threads())));
        } else {
            lines.add(normal(String.format(Locale.ROOT, "samples %d/%d   threads %d", s.samplesDone(),
                    s.samplesTotal(), s.threads())));
        }
        lines.add(normal(String.format(Locale.ROOT, "shading %s   %sdepth %d   %sspeed %s/s", s.shading().key(),
                s.transport().physical() ? "integrator " + s.transport().key() + "   " : "", s.depth(),
                s.lens().isEmpty() ? "" : s.lens() + "   ", number(s.speed()))));
        if (!s.view().isEmpty()) {
            lines.add(normal(s.view()));
        }
        lines.add(normal(s.scene()));
        if (!s.message().isEmpty()) {
            for (String line : s.message().split("\n")) { // a camera block (key C) is several lines
                lines.add(new Line(line, Tone.NOTE));
            }
        }
        if (!s.error().isEmpty()) {
            lines.add(new Line(s.error(), Tone.ERROR));
        }
        if (!s.renderError().isEmpty()) {
            lines.add(new Line(s.renderError(), Tone.ERROR));
        }
        lines.add(new Line("H hides this, ? shows the keys", Tone.NOTE));
        return lines;
    }

    /**
     * Breaks lines wider than {@code max} (as measured by {@code width}) at spaces, or anywhere in a word
     * too long for a line; continuation lines are indented by two spaces.
     */
    public static List<Line> wrap(List<Line> lines, ToIntFunction<String> width, int max) {
        List<Line> out = new ArrayList<>();
        for (Line line : lines) {
            String indent = "";
            String rest = line.text();
            while (width.applyAsInt(indent + rest) > max && rest.length() > 1) {
                int cut = rest.length() - 1;
                while (cut > 1 && width.applyAsInt(indent + rest.substring(0, cut)) > max) {
                    cut--;
                }
                int space = rest.lastIndexOf(' ', cut);
                int end = space > 0 ? space : cut; // at least one character each time: it ends
                out.add(new Line(indent + rest.substring(0, end), line.tone()));
                rest = rest.substring(end).stripLeading();
                indent = "  ";
            }
            if (!rest.isEmpty()) {
                out.add(new Line(indent + rest, line.tone()));
            }
        }
        return out;
    }

    private static Line normal(String text) {
        return new Line(text, Tone.NORMAL);
    }

    private static String number(double x) {
        return x >= 100 || x == Math.rint(x) ? String.format(Locale.ROOT, "%.0f", x)
                : String.format(Locale.ROOT, x >= 1 ? "%.2f" : "%.3g", x);
    }
}
