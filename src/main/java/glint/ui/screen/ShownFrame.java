package glint.ui.screen;

import java.awt.image.BufferedImage;

/**
 * A complete frame handed from the engine to the display. The image is never written again after it
 * is handed over: the engine makes a new one for every frame, so the display cannot show half of one
 * frame and half of the next.
 *
 * @param image  the rendered frame, 8-bit sRGB, at the render resolution (scaled up to the window)
 * @param stats  what the overlay shows
 * @param serial counts frames rendered since the engine started
 */
public record ShownFrame(BufferedImage image, FrameStats stats, long serial) {
}
