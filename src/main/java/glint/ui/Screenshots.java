package glint.ui;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.function.Supplier;

/** Saves the view as {@code glint-yyyyMMdd-HHmmss-SSS.png} in a folder (the working directory). */
public final class Screenshots {

    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS");

    private final Path folder;
    private final Supplier<LocalDateTime> now;

    public Screenshots(Path folder) {
        this(folder, LocalDateTime::now);
    }

    Screenshots(Path folder, Supplier<LocalDateTime> now) {
        this.folder = folder;
        this.now = now;
    }

    public Path folder() {
        return folder;
    }

    /**
     * Writes the image to a new file and returns its path; never overwrites a file. The PNG is written
     * aside first and renamed when complete, so that the file never exists half written.
     */
    public Path save(BufferedImage image) throws IOException {
        Path part = Files.createTempFile(folder, ".glint-", ".png.part");
        try {
            try (OutputStream out = Files.newOutputStream(part, StandardOpenOption.WRITE)) {
                glint.image.ImageWriter.writePng(image, out);
            }
            String stamp = "glint-" + STAMP.format(now.get());
            Path file = folder.resolve(stamp + ".png");
            for (int n = 1; Files.exists(file); n++) { // two in one millisecond
                file = folder.resolve(stamp + "-" + n + ".png");
            }
            return Files.move(part, file, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException | RuntimeException e) {
            deleteQuietly(part, e);
            throw e;
        }
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

    private static void deleteQuietly(Path file, Exception cause) {
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            cause.addSuppressed(e);
        }
    }
}
