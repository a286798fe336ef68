package glint.image;

import glint.render.FrameBuffer;
import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Iterator;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * Writes a frame as an sRGB PNG or a linear PFM, chosen by the file's extension. The file is written
 * to a temporary file in the same folder and renamed into place when complete: a failed write (a full
 * disk) leaves no truncated file and keeps an image of the same name as it was.
 */
public final class ImageWriter {

    /** Writes one file's content to a stream. */
    @FunctionalInterface
    public interface Content {
        void writeTo(OutputStream out) throws IOException;
    }

    private ImageWriter() {
    }

    /** True when the path ends in .png or .pfm (any case). */
    public static boolean isSupported(Path path) {
        String name = path.getFileName().toString().toLowerCase(Locale.ROOT);
        return name.endsWith(".png") || name.endsWith(".pfm");
    }

    public static void write(FrameBuffer frame, Path path) throws IOException {
        write(frame, path, temporaryBeside(path));
    }

    /**
     * Writes the frame to {@code temp} (made by {@link #temporaryBeside}) and renames it to
     * {@code path}; {@code temp} is gone afterwards, whether the write succeeded or not.
     */
    public static void write(FrameBuffer frame, Path path, Path temp) throws IOException {
        String name = path.getFileName().toString().toLowerCase(Locale.ROOT);
        Content content = name.endsWith(".pfm") ? out -> writePfm(frame, out) : out -> writePng(toImage(frame), out);
        writeAtomically(path, temp, content);
    }

    /**
     * A new empty file in the folder of {@code path}, named after it and hidden ({@code .out.png.1a2b.part}),
     * to be renamed to it when written; made with the folder's usual permissions.
     */
    public static Path temporaryBeside(Path path) throws IOException {
        Path folder = path.toAbsolutePath().getParent();
        // not Files.createTempFile: its file is private (0600), and the image would keep that mode
        for (int attempt = 0; ; attempt++) {
            Path temp = folder.resolve("." + path.getFileName() + "." + Long.toHexString(System.nanoTime()) + ".part");
            try {
                return Files.createFile(temp);
            } catch (java.nio.file.FileAlreadyExistsException e) {
                if (attempt == 100) {
                    throw e;
                }
            }
        }
    }

    /** Writes {@code content} to {@code temp}, then renames it to {@code path}; deletes temp on failure. */
    public static void writeAtomically(Path path, Path temp, Content content) throws IOException {
        try {
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(temp), 1 << 16)) {
                content.writeTo(out);
            }
            try {
                Files.move(temp, path, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, path, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temp);
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

    /**
     * The image as PNG to a stream. The encoder writes through a stream of our own (not ImageIO's
     * file cache, whose clean-up thread prints a stack trace when a write fails).
     */
    public static void writePng(BufferedImage image, OutputStream out) throws IOException {
        Iterator<javax.imageio.ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
        if (!writers.hasNext()) {
            throw new IOException("no PNG writer available");
        }
        javax.imageio.ImageWriter writer = writers.next();
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.write(image);
        } finally {
            writer.dispose();
        }
    }

    public static void writePng(FrameBuffer frame, Path path) throws IOException {
        writeAtomically(path, temporaryBeside(path), out -> writePng(toImage(frame), out));
    }

    public static void writePfm(FrameBuffer frame, Path path) throws IOException {
        writeAtomically(path, temporaryBeside(path), out -> writePfm(frame, out));
    }

    /** Portable Float Map: "PF", little-endian (scale -1), rows bottom to top, linear RGB; row by row. */
    public static void writePfm(FrameBuffer frame, OutputStream out) throws IOException {
        int w = frame.width(), h = frame.height();
        out.write(("PF\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
        ByteBuffer row = ByteBuffer.allocate(12 * w).order(ByteOrder.LITTLE_ENDIAN);
        float[] rgb = frame.rgb();
        for (int y = h - 1; y >= 0; y--) {
            row.clear();
            for (long i = 3L * y * w, end = 3L * (y + 1) * w; i < end; i++) {
                row.putFloat(rgb[(int) i]);
            }
            out.write(row.array(), 0, row.position());
        }
    }
}
