package glint.image;

import glint.render.FrameBuffer;
import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;

/** Writes a frame as an sRGB PNG or a linear PFM, chosen by the file's extension. */
public final class ImageWriter {

    private ImageWriter() {
    }

    /** True when the path ends in .png or .pfm (any case). */
    public static boolean isSupported(Path path) {
        String name = path.getFileName().toString().toLowerCase(Locale.ROOT);
        return name.endsWith(".png") || name.endsWith(".pfm");
    }

    public static void write(FrameBuffer frame, Path path) throws IOException {
        String name = path.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".pfm")) {
            writePfm(frame, path);
        } else {
            writePng(frame, path);
        }
    }

    /** The frame as an 8-bit sRGB image. */
    public static BufferedImage toImage(FrameBuffer frame) {
        BufferedImage image = new BufferedImage(frame.width(), frame.height(), BufferedImage.TYPE_INT_RGB);
        float[] rgb = frame.rgb();
        int[] row = new int[frame.width()];
        for (int y = 0; y < frame.height(); y++) {
            for (int x = 0; x < frame.width(); x++) {
                int i = 3 * (y * frame.width() + x);
                row[x] = Srgb.to8Bit(rgb[i]) << 16 | Srgb.to8Bit(rgb[i + 1]) << 8 | Srgb.to8Bit(rgb[i + 2]);
            }
            image.setRGB(0, y, frame.width(), 1, row, 0, frame.width());
        }
        return image;
    }

    public static void writePng(FrameBuffer frame, Path path) throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(path))) {
            if (!ImageIO.write(toImage(frame), "png", out)) {
                throw new IOException("no PNG writer available");
            }
        }
    }

    /** Portable Float Map: "PF", little-endian (scale -1), rows bottom to top, linear RGB. */
    public static void writePfm(FrameBuffer frame, Path path) throws IOException {
        int w = frame.width(), h = frame.height();
        byte[] header = ("PF\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII);
        ByteBuffer body = ByteBuffer.allocate(12 * w * h).order(ByteOrder.LITTLE_ENDIAN);
        float[] rgb = frame.rgb();
        for (int y = h - 1; y >= 0; y--) {
            for (int i = 3 * y * w, end = 3 * (y + 1) * w; i < end; i++) {
                body.putFloat(rgb[i]);
            }
        }
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(path))) {
            out.write(header);
            out.write(body.array());
        }
    }
}
