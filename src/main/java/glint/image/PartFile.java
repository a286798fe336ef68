package glint.image;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.SecureDirectoryStream;
import java.nio.file.StandardOpenOption;
import java.util.EnumSet;

/**
 * The hidden temporary file an image is written to before it is renamed into place
 * ({@code .out.png.1a2b.part}, see {@link ImageWriter#temporaryBeside}), made and deleted through a
 * handle on its folder: a folder renamed or moved while the image is made keeps no leftover, since the
 * file is deleted wherever the folder is by then. Where the platform has no such handles (or the folder
 * cannot be listed), by its path. Any thread may delete it.
 */
public final class PartFile implements AutoCloseable {

    private final Path path;
    private final Path name;
    private SecureDirectoryStream<Path> folder; // null: by path

    private PartFile(Path path, SecureDirectoryStream<Path> folder) {
        this.path = path;
        this.name = path.getFileName();
        this.folder = folder;
    }

    /** Makes the empty hidden file beside {@code image} (in its folder, named after it). */
    public static PartFile beside(Path image) throws IOException {
        Path parent = image.toAbsolutePath().getParent();
        SecureDirectoryStream<Path> folder = open(parent);
        if (folder == null) {
            return new PartFile(ImageWriter.temporaryBeside(image), null);
        }
        try {
            for (int attempt = 0; ; attempt++) {
                Path path = ImageWriter.temporaryName(image);
                try {
                    folder.newByteChannel(path.getFileName(), EnumSet.of(StandardOpenOption.CREATE_NEW,
                            StandardOpenOption.WRITE)).close();
                    return new PartFile(path, folder);
                } catch (FileAlreadyExistsException e) {
                    if (attempt == 100) {
                        throw e;
                    }
                }
            }
        } catch (IOException | RuntimeException e) {
            folder.close();
            throw e;
        }
    }

    /** The folder as a handle, or null where there is none. */
    private static SecureDirectoryStream<Path> open(Path folder) {
        try {
            DirectoryStream<Path> stream = Files.newDirectoryStream(folder);
            if (stream instanceof SecureDirectoryStream<Path> secure) {
                return secure;
            }
            stream.close();
        } catch (IOException | SecurityException | UnsupportedOperationException e) {
            // no handle: the path does (a folder that may be written but not listed, mode 0333)
        }
        return null;
    }

    /** The file's path as it was made (its folder may have moved since). */
    public Path path() {
        return path;
    }

    /** Deletes the file where it is now; nothing if it is gone (renamed into place, or deleted before). */
    public synchronized void delete() {
        try {
            if (folder != null) {
                folder.deleteFile(name);
            } else {
                Files.deleteIfExists(path);
            }
        } catch (NoSuchFileException e) {
            // gone already
        } catch (IOException | SecurityException e) {
            // cannot be deleted (the folder made read-only since): nothing more can be done
        }
    }

    /** Deletes the file and lets go of its folder. */
    @Override
    public synchronized void close() {
        delete();
        if (folder != null) {
            try {
                folder.close();
            } catch (IOException e) {
                // the handle is released all the same
            }
            folder = null;
        }
    }
}
