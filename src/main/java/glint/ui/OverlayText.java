package glint.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The overlay's lines for a frame's stats (key H shows and hides it). */
final class OverlayText {

    /** A line of the overlay; {@code tone} picks its colour. */
    record Line(String text, Tone tone) {
    }

    enum Tone { NORMAL, NOTE, ERROR }

    private OverlayText() {
    }

    static List<Line> lines(FrameStats s) {
        List<Line> lines = new ArrayList<>();
        if (Double.isNaN(s.fps())) {
            lines.add(normal(String.format(Locale.ROOT, "%s   last frame %.1f ms",
                    s.refined() ? "idle: image complete" : "idle", s.msPerFrame())));
        } else {
            lines.add(normal(String.format(Locale.ROOT, "%.1f fps   %.1f ms/frame", s.fps(), s.msPerFrame())));
        }
        String scale = s.renderWidth() == s.viewWidth() ? "full" : String.format(Locale.ROOT, "1/%.2f",
                (double) s.viewWidth() / Math.max(1, s.renderWidth()));
        lines.add(normal(String.format(Locale.ROOT, "render %dx%d (%s of %dx%d)%s", s.renderWidth(),
                s.renderHeight(), scale, s.viewWidth(), s.viewHeight(), s.moving() ? "  moving" : "")));
        lines.add(normal(String.format(Locale.ROOT, "samples %d/%d   threads %d", s.samplesDone(),
                s.samplesTotal(), s.threads())));
        lines.add(normal(String.format(Locale.ROOT, "shading %s   depth %d   speed %s/s", s.shading().key(),
                s.depth(), number(s.speed()))));
        lines.add(normal(s.scene()));
        if (!s.message().isEmpty()) {
            lines.add(new Line(s.message(), Tone.NOTE));
        }
        if (!s.error().isEmpty()) {
            lines.add(new Line(s.error(), Tone.ERROR));
        }
        lines.add(new Line("H hides this, ? shows the keys", Tone.NOTE));
        return lines;
    }

    private static Line normal(String text) {
        return new Line(text, Tone.NORMAL);
    }

    private static String number(double x) {
        return x >= 100 || x == Math.rint(x) ? String.format(Locale.ROOT, "%.0f", x)
                : String.format(Locale.ROOT, x >= 1 ? "%.2f" : "%.3g", x);
    }
}
