package glint.ui.capture;

import glint.image.ImageWriter;
import glint.image.PartFile;
import glint.image.PartGuard;
import glint.input.InputException;
import glint.still.OutputFile;
import glint.ui.frames.ResolutionGovernor;
import glint.ui.screen.WindowImages;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.function.Supplier;

/** Saves the view as {@code glint-yyyyMMdd-HHmmss-SSS.png} in a folder (the working directory). */
public final class Screenshots {

    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS");

    /** Opens the stream a screenshot's PNG is written to, on its hidden file. */
    @FunctionalInterface
    interface Opener {
        OutputStream open(Path part) throws IOException;
    }

    private final Path folder;
    private final Supplier<LocalDateTime> now;
    private final Opener opener;

    public Screenshots(Path folder) {
        this(folder, LocalDateTime::now);
    }

    Screenshots(Path folder, Supplier<LocalDateTime> now) {
        this(folder, now, part -> Files.newOutputStream(part, StandardOpenOption.WRITE));
    }

    Screenshots(Path folder, Supplier<LocalDateTime> now, Opener opener) {
        this.folder = folder;
        this.now = now;
        this.opener = opener;
    }

    public Path folder() {
        return folder;
    }

    /**
     * Writes the image to a new file and returns its path; never overwrites a file. The PNG is written
     * aside first and renamed when complete, so that the file never exists half written.
     */
    public Path save(BufferedImage image) throws IOException {
        return save("glint", ".png", part -> {
            try (OutputStream out = opener.open(part)) {
                ImageWriter.writePng(image, out);
            }
        });
    }

    /**
     * Saves the view's image at {@code size} (scaled as shown) and returns what the overlay says: where it
     * went, or why not (also on {@code err}). {@code sizeLimit} says why the size is below the window's.
     */
    String saveView(BufferedImage view, ResolutionGovernor.Size size, String sizeLimit, PrintWriter err) {
        try {
            Path file = save(WindowImages.scaled(view, size.width(), size.height()));
            return "saved " + file + (sizeLimit.isEmpty() ? ""
                    : " at " + size.width() + "x" + size.height() + " (at most " + sizeLimit + ")");
        } catch (IOException | RuntimeException | OutOfMemoryError e) {
            String why = "screenshot not saved: " + (e instanceof Exception x ? why(x) : "out of memory");
            err.println("glint: " + why);
            return why;
        }
    }

    /** Writes a file's content to a temporary file. */
    @FunctionalInterface
    interface Content {
        void writeTo(Path part) throws IOException;
    }

    /**
     * Writes a new file {@code prefix-yyyyMMdd-HHmmss-SSS.ext} ({@code -1}, {@code -2} when taken) and returns
     * its path: written aside, with the folder's usual permissions as every output, and renamed when complete.
     */
    Path save(String prefix, String extension, Content content) throws IOException {
        // not Files.createTempFile: its file is private (0600), and the image would keep that mode
        PartFile part = PartFile.beside(folder.resolve(prefix + extension));
        PartGuard guard = PartGuard.of(List.of(part.path()), ENDED);
        Path file = name(prefix, extension);
        try {
            content.writeTo(part.path());
            return Files.move(part.path(), Files.exists(file) ? name(prefix, extension) : file,
                    StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException e) { // a full disk: the file, and the system's reason, not the encoder's words
            throw new IOException("cannot write " + InputException.quotePath(file) + ": " + OutputFile.reason(cause(e)), e);
        } finally {
            part.close(); // gone already if it was renamed; else deleted, wherever the folder is now
            guard.close();
        }
    }

    /** What the PNG encoder met, under its "I/O error writing PNG file!". */
    private static IOException cause(IOException e) {
        return e instanceof javax.imageio.IIOException && e.getCause() instanceof IOException met ? met : e;
    }

    /** What a guard says if the program ends too abruptly to delete a screenshot's hidden file itself. */
    private static final String ENDED = "glint: the program ended before the screenshot was written; nothing "
            + "written, its hidden temporary file removed";

    /** A name no file has yet: {@code prefix-yyyyMMdd-HHmmss-SSS.ext}, or with {@code -1}, {@code -2}. */
    Path name(String prefix, String extension) {
        String stamp = prefix + "-" + STAMP.format(now.get());
        Path file = folder.resolve(stamp + extension);
        for (int n = 1; Files.exists(file); n++) { // two in one millisecond
            file = folder.resolve(stamp + "-" + n + extension);
        }
        return file;
    }

    /** Why a save failed, in words: {@code <folder>: permission denied}, ... */
    public String why(Exception e) {
        if (e instanceof AccessDeniedException) {
            return folder + ": permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return folder + ": no such folder";
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return folder + ": " + f.getReason();
        }
        return e.getMessage() != null ? e.getMessage() : e.toString();
    }

}
