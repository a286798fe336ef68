package glint.ui.view;

import glint.config.Limits;
import glint.ui.frames.ResolutionGovernor;
import java.io.PrintWriter;
import java.util.Locale;

/**
 * The window's drawing area and the frame size budget for it ({@link FrameBudget}): the size frames are
 * rendered at, and why they are smaller than the window when the budget binds. Others read it; only its
 * {@link SceneView} changes it ({@link SceneView#resized}), and starts the frame over when it does. Engine
 * thread only.
 */
public final class FrameSize {

    private final StatusLine status;
    private final PrintWriter err;
    private int width;
    private int height;
    private FrameBudget budget;
    private String sizeLimit = ""; // why frames are smaller than the window, or empty

    /** A window of this size; its {@link SceneView} sets the budget ({@link #check}) before the first frame. */
    public FrameSize(int width, int height, StatusLine status, PrintWriter err) {
        this.width = width;
        this.height = height;
        this.status = status;
        this.err = err;
    }

    /** The window is now {@code w} x {@code h}; true if that is a new size (then {@link #check} it). */
    boolean resize(int w, int h) {
        if (w == width && h == height) {
            return false;
        }
        width = w;
        height = h;
        return true;
    }

    /** The frame size budget under these limits for the window's size now; says once when it starts to bind. */
    void check(Limits limits) {
        budget = FrameBudget.of(limits, Runtime.getRuntime().maxMemory());
        boolean over = budget.binds(width, height);
        if (over && sizeLimit.isEmpty()) {
            ResolutionGovernor.Size size = budget.fit(width, height, 1);
            String line = String.format(Locale.ROOT, "the window is %dx%d; frames are rendered at %dx%d, at most %s",
                    width, height, size.width(), size.height(), budget.why());
            err.println("glint: " + line);
            status.note(line);
        }
        sizeLimit = over ? budget.why() : "";
    }

    /** The render size of the window at scale {@code s}, within the budget. */
    public ResolutionGovernor.Size fit(double s) {
        return budget.fit(width, height, s);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Why frames are smaller than the window ({@code 10,000 pixels (max_image_pixels)}), or empty. */
    public String sizeLimit() {
        return sizeLimit;
    }
}
