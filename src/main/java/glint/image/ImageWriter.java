package glint.image;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.io.BufferedOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Iterator;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.imageio.event.IIOWriteProgressListener;
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

    /** The most characters of the image's name a temporary file's name repeats. */
    static final int MAX_TEMP_STEM = 60;

    private ImageWriter() {
    }

    /** True when the path ends in .png or .pfm (any case). */
    public static boolean isSupported(Path path) {
        String name = path.getFileName().toString().toLowerCase(Locale.ROOT);
        return name.endsWith(".png") || name.endsWith(".pfm");
    }

    /**
     * Writes the frame to {@code path} in the format its name asks for, through a temporary file beside it; a
     * PNG through the standard view transform (no exposure, clamped).
     */
    public static void write(FrameBuffer frame, Path path) throws IOException {
        write(frame, ViewTransform.STANDARD, path);
    }

    /** Writes the frame to {@code path}, a PNG through {@code view} (a PFM holds the linear values whatever it is). */
    public static void write(FrameBuffer frame, ViewTransform view, Path path) throws IOException {
        writeAtomically(path, temporaryBeside(path), content(frame, view, path, new Watcher() { }));
    }

    /**
     * What the caller of a long write sees and decides: how far it is, and whether to give up (the still
     * was cancelled, the program is being stopped).
     */
    public interface Watcher {
        /** The fraction of the write done, from 0 to 1. */
        default void progress(double fraction) {
        }

        /** True when the write should stop; it then fails with an {@link InterruptedIOException}. */
        default boolean cancelled() {
            return false;
        }
    }

    /**
     * Writes the frame to {@code temp} in the format {@code path}'s name asks for, reporting progress to
     * the watcher and stopping when it says so; renames nothing (see {@link #rename}).
     */
    public static void writeTemporary(FrameBuffer frame, Path path, Path temp, Watcher watcher) throws IOException {
        writeTemporary(frame, ViewTransform.STANDARD, path, temp, watcher);
    }

    /** {@link #writeTemporary(FrameBuffer, Path, Path, Watcher)} with a PNG made through {@code view}. */
    public static void writeTemporary(FrameBuffer frame, ViewTransform view, Path path, Path temp, Watcher watcher)
            throws IOException {
        Content content = content(frame, view, path, watcher);
        try { // the file was made beforehand: deleted since (a cancel), it is not made again
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(temp, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING), 1 << 16)) {
                content.writeTo(new CancellableStream(out, watcher));
            }
        } catch (IOException e) {
            if (watcher.cancelled() && !(e instanceof InterruptedIOException)) { // the encoder wraps what it met
                InterruptedIOException stopped = new InterruptedIOException("interrupted");
                stopped.initCause(e);
                throw stopped;
            }
            if (e instanceof javax.imageio.IIOException && e.getCause() instanceof IOException cause) {
                throw cause; // "I/O error writing PNG file!" says less than what the encoder met: "File too large"
            }
            throw e;
        }
    }

    /** The frame in the format {@code path}'s name asks for: a linear PFM, else an sRGB PNG through {@code view}. */
    private static Content content(FrameBuffer frame, ViewTransform view, Path path, Watcher watcher) {
        String name = path.getFileName().toString().toLowerCase(Locale.ROOT);
        return name.endsWith(".pfm") ? out -> writePfm(frame, out, watcher)
                : out -> writePng(toImage(frame, view, watcher), out, watcher);
    }

    /** Stops a write at its next bytes once the watcher says so. */
    private static final class CancellableStream extends FilterOutputStream {
        private final Watcher watcher;

        CancellableStream(OutputStream out, Watcher watcher) {
            super(out);
            this.watcher = watcher;
        }

        @Override
        public void write(int b) throws IOException {
            check(watcher);
            out.write(b);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            check(watcher);
            out.write(b, off, len);
        }
    }

    private static void check(Watcher watcher) throws InterruptedIOException {
        if (watcher.cancelled()) {
            throw new InterruptedIOException("interrupted");
        }
    }

    /**
     * A new empty file in the folder of {@code path}, named after it and hidden ({@code .out.png.1a2b.part}),
     * to be renamed to it when written; made with the folder's usual permissions.
     */
    public static Path temporaryBeside(Path path) throws IOException {
        // not Files.createTempFile: its file is private (0600), and the image would keep that mode
        for (int attempt = 0; ; attempt++) {
            try {
                return Files.createFile(temporaryName(path));
            } catch (java.nio.file.FileAlreadyExistsException e) {
                if (attempt == 100) {
                    throw e;
                }
            }
        }
    }

    /** A name for a temporary file beside {@code path}, as {@link #temporaryBeside} makes it (not made here). */
    static Path temporaryName(Path path) {
        Path folder = path.toAbsolutePath().getParent();
        String name = path.getFileName().toString();
        if (name.length() > MAX_TEMP_STEM) { // the suffix must not push a long name past the folder's limit
            name = name.substring(0, Character.isHighSurrogate(name.charAt(MAX_TEMP_STEM - 1)) ? MAX_TEMP_STEM - 1 : MAX_TEMP_STEM);
        }
        return folder.resolve("." + name + "." + Long.toHexString(System.nanoTime()) + ".part");
    }

    /** Writes {@code content} to {@code temp}, then renames it to {@code path}; deletes temp on failure. */
    public static void writeAtomically(Path path, Path temp, Content content) throws IOException {
        try {
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(temp), 1 << 16)) {
                content.writeTo(out);
            }
            rename(temp, path);
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** Puts a complete temporary file in place under the image's name, replacing a file of that name. */
    public static void rename(Path temp, Path path) throws IOException {
        try {
            Files.move(temp, path, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(temp, path, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** The frame as an 8-bit sRGB image, dithered ({@link Dither}), through the standard view transform. */
    public static BufferedImage toImage(FrameBuffer frame) {
        return toImage(frame, ViewTransform.STANDARD);
    }

    /** The frame as an 8-bit sRGB image through {@code view}, dithered ({@link Dither}). */
    public static BufferedImage toImage(FrameBuffer frame, ViewTransform view) {
        try {
            return toImage(frame, view, new Watcher() { });
        } catch (InterruptedIOException e) {
            throw new IllegalStateException(e); // a watcher that never cancels
        }
    }

    /** The share of a PNG's write spent making its 8-bit image; the encoding is the rest. */
    private static final double IMAGE_SHARE = 0.2;

    private static BufferedImage toImage(FrameBuffer frame, ViewTransform view, Watcher watcher)
            throws InterruptedIOException {
        BufferedImage image = new BufferedImage(frame.width(), frame.height(), BufferedImage.TYPE_INT_RGB);
        float[] rgb = frame.rgb();
        int[] pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData(); // row by row, 0xRRGGBB
        double[] scratch = new double[3];
        for (int y = 0; y < frame.height(); y++) {
            for (int x = 0, p = y * frame.width(); x < frame.width(); x++, p++) {
                int i = 3 * p;
                pixels[p] = view.pixel(rgb[i], rgb[i + 1], rgb[i + 2], Dither.levels(x, y), scratch);
            }
            if ((y & 63) == 63) {
                check(watcher);
                watcher.progress(IMAGE_SHARE * y / frame.height());
            }
        }
        return image;
    }

    /**
     * The image as PNG to a stream. The encoder writes through a stream of our own (not ImageIO's
     * file cache, whose clean-up thread prints a stack trace when a write fails).
     */
    public static void writePng(BufferedImage image, OutputStream out) throws IOException {
        writePng(image, out, new Watcher() { });
    }

    private static void writePng(BufferedImage image, OutputStream out, Watcher watcher) throws IOException {
        Iterator<javax.imageio.ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
        if (!writers.hasNext()) {
            throw new IOException("no PNG writer available");
        }
        javax.imageio.ImageWriter writer = writers.next();
        writer.addIIOWriteProgressListener(new IIOWriteProgressListener() {
            @Override
            public void imageProgress(javax.imageio.ImageWriter source, float percentageDone) {
                watcher.progress(IMAGE_SHARE + (1 - IMAGE_SHARE) * percentageDone / 100);
                if (watcher.cancelled()) {
                    source.abort();
                }
            }

            @Override
            public void imageStarted(javax.imageio.ImageWriter source, int imageIndex) {
            }

            @Override
            public void imageComplete(javax.imageio.ImageWriter source) {
            }

            @Override
            public void thumbnailStarted(javax.imageio.ImageWriter source, int imageIndex, int thumbnailIndex) {
            }

            @Override
            public void thumbnailProgress(javax.imageio.ImageWriter source, float percentageDone) {
            }

            @Override
            public void thumbnailComplete(javax.imageio.ImageWriter source) {
            }

            @Override
            public void writeAborted(javax.imageio.ImageWriter source) {
            }
        });
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.write(image);
        } finally {
            writer.dispose();
        }
        check(watcher); // an aborted encoding returns early, its file incomplete
    }

    public static void writePfm(FrameBuffer frame, Path path) throws IOException {
        writeAtomically(path, temporaryBeside(path), out -> writePfm(frame, out));
    }

    /** The size in bytes of a PFM of this size, as {@link #writePfm(FrameBuffer, OutputStream)} writes it. */
    public static long pfmBytes(int width, int height) {
        return pfmHeader(width, height).length + 12L * width * height;
    }

    private static byte[] pfmHeader(int width, int height) {
        return ("PF\n" + width + " " + height + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII);
    }

    /** Portable Float Map: "PF", little-endian (scale -1), rows bottom to top, linear RGB; row by row. */
    public static void writePfm(FrameBuffer frame, OutputStream out) throws IOException {
        writePfm(frame, out, new Watcher() { });
    }

    private static void writePfm(FrameBuffer frame, OutputStream out, Watcher watcher) throws IOException {
        int w = frame.width(), h = frame.height();
        out.write(pfmHeader(w, h));
        ByteBuffer row = ByteBuffer.allocate(12 * w).order(ByteOrder.LITTLE_ENDIAN);
        float[] rgb = frame.rgb();
        for (int y = h - 1; y >= 0; y--) {
            row.clear();
            for (long i = 3L * y * w, end = 3L * (y + 1) * w; i < end; i++) {
                row.putFloat(rgb[(int) i]);
            }
            out.write(row.array(), 0, row.position());
            if ((y & 63) == 0) {
                watcher.progress((h - y) / (double) h);
            }
        }
    }
}
