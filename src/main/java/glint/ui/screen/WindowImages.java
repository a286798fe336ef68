package glint.ui.screen;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;

/** How a frame fills the window: scaled to the drawing area, nearest pixel (cheap and honest). */
public final class WindowImages {

    private WindowImages() {
    }

    /** Draws {@code image} over the area (0, 0, width, height); black where there is none. */
    public static void draw(Graphics2D g, BufferedImage image, int width, int height) {
        if (image == null) {
            g.setColor(Color.BLACK);
            g.fillRect(0, 0, width, height);
            return;
        }
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        if (image.getWidth() == width && image.getHeight() == height) {
            g.drawImage(image, 0, 0, null);
        } else {
            g.drawImage(image, 0, 0, width, height, null);
        }
    }

    /** The image as the window shows it at width x height (itself when it has that size). */
    public static BufferedImage scaled(BufferedImage image, int width, int height) {
        if (image.getWidth() == width && image.getHeight() == height) {
            return image;
        }
        BufferedImage out = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        try {
            draw(g, image, width, height);
        } finally {
            g.dispose();
        }
        return out;
    }
}
