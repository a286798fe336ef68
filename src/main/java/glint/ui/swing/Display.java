package glint.ui.swing;

import glint.ui.input.KeyBindings;
import glint.ui.screen.OverlayText;
import glint.ui.screen.Presenter;
import glint.ui.screen.ShownFrame;
import glint.ui.screen.WindowImages;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.RenderingHints;
import java.awt.Toolkit;
import java.awt.Window;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;

/**
 * The window's drawing area. The engine hands it complete frames ({@link #present}, any thread);
 * painting, on the Swing event thread, draws the latest one scaled to the area, then the overlay.
 * Painting never waits for the engine: it takes whatever complete frame is newest.
 */
public final class Display extends JPanel implements Presenter {

    private static final Color BOX = new Color(0, 0, 0, 170);
    private static final Color TEXT = new Color(235, 235, 235);
    private static final Color NOTE = new Color(255, 214, 110);
    private static final Color ERROR = new Color(255, 110, 100);
    private static final int PAD = 8;

    private final AtomicReference<ShownFrame> latest = new AtomicReference<>();
    private volatile boolean overlay = true;
    private volatile boolean help;
    private final Font font = new Font(Font.MONOSPACED, Font.PLAIN, 13);

    public Display(int width, int height) {
        setPreferredSize(new Dimension(width, height));
        setBackground(Color.BLACK);
        setOpaque(true);
        setFocusable(true);
        setFocusTraversalKeysEnabled(false); // Tab toggles the shading
    }

    @Override
    public void present(ShownFrame frame) {
        latest.set(frame);
        repaint();
    }

    @Override
    public void title(String title) {
        SwingUtilities.invokeLater(() -> {
            Window w = SwingUtilities.getWindowAncestor(this);
            if (w instanceof JFrame f) {
                f.setTitle(title);
            }
        });
    }

    /** The frame painted last or about to be painted. */
    public ShownFrame shown() {
        return latest.get();
    }

    public boolean overlayVisible() {
        return overlay;
    }

    public boolean helpVisible() {
        return help;
    }

    public void toggleOverlay() {
        overlay = !overlay;
        repaint();
    }

    public void toggleHelp() {
        help = !help;
        repaint();
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics;
        ShownFrame frame = latest.get();
        WindowImages.draw(g, frame == null ? null : frame.image(), getWidth(), getHeight());
        g.setFont(font);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        int y = PAD;
        List<OverlayText.Line> keys = help ? KeyBindings.helpLines().stream()
                .map(t -> new OverlayText.Line(t, OverlayText.Tone.NORMAL)).toList() : List.of();
        if (overlay && frame != null) {
            List<OverlayText.Line> stats = OverlayText.lines(frame.stats());
            int rows = stats.size() + keys.size();
            // the help goes below the overlay; where both do not fit, the help alone is shown
            if (!help || rows * g.getFontMetrics().getHeight() + 5 * PAD <= getHeight()) {
                y = box(g, stats, y) + PAD;
            }
        }
        if (help) { // in a smaller font where the window is too low for all of it
            for (float size = font.getSize2D(); size > 8 && (keys.size() * g.getFontMetrics().getHeight() + 3 * PAD
                    > getHeight() - y); size -= 0.5f) {
                g.setFont(font.deriveFont(size - 0.5f));
            }
            box(g, keys, y);
        }
        // X11 buffers drawing requests; without a flush a frame can sit unseen until other traffic comes
        Toolkit.getDefaultToolkit().sync();
    }

    /** Draws lines in a dark box at the top left, wrapped to the window; returns the box's bottom. */
    private int box(Graphics2D g, List<OverlayText.Line> unwrapped, int top) {
        return box(g, unwrapped, PAD, top, getWidth() - 4 * PAD);
    }

    /** Draws lines in a dark box from ({@code left}, {@code top}), wrapped to {@code wrapWidth}; returns its bottom. */
    private int box(Graphics2D g, List<OverlayText.Line> unwrapped, int left, int top, int wrapWidth) {
        FontMetrics m = g.getFontMetrics();
        List<OverlayText.Line> lines = OverlayText.wrap(unwrapped, m::stringWidth,
                Math.max(m.charWidth('m') * 20, wrapWidth));
        int width = 0;
        for (OverlayText.Line line : lines) {
            width = Math.max(width, m.stringWidth(line.text()));
        }
        int height = lines.size() * m.getHeight();
        g.setColor(BOX);
        g.fillRoundRect(left, top, width + 2 * PAD, height + 2 * PAD, 8, 8);
        int y = top + PAD + m.getAscent();
        for (OverlayText.Line line : lines) {
            g.setColor(switch (line.tone()) {
                case NORMAL -> TEXT;
                case NOTE -> NOTE;
                case ERROR -> ERROR;
            });
            g.drawString(line.text(), left + PAD, y);
            y += m.getHeight();
        }
        return top + height + 2 * PAD;
    }

}
