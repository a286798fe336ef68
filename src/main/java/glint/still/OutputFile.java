package glint.still;

import glint.image.ImageWriter;
import glint.image.PartFile;
import glint.input.InputException;
import glint.input.TextFiles;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.LinkOption;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFileAttributes;
import java.util.List;
import java.util.Locale;

/**
 * An image file of a still, checked before any work: everything that would make the final rename fail
 * or lose a file is refused up front ({@link StillRefused}). The image is then written to a hidden
 * temporary file beside it (made here, so that an unwritable folder is found now) and renamed over it
 * when complete ({@link StillRun}).
 */
public final class OutputFile {

    /** Refuses a PFM output of this size that would be larger than this process may write (ulimit -f). */
    static void checkSize(Path output, int width, int height) throws StillRefused {
        if (output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".pfm")) {
            long size = ImageWriter.pfmBytes(width, height);
            long limit = fileSizeLimit(Path.of("/proc/self/limits"));
            if (size > limit) {
                String[] sizes = TextFiles.sizes(size, limit);
                throw refused(String.format(Locale.ROOT, "a %dx%d PFM is %s, more than the largest file this process may "
                        + "write (%s, ulimit -f); render a smaller image, a PNG, or raise the limit",
                        width, height, sizes[0], sizes[1]));
            }
        }
    }

    /** The sticky bit of a folder's mode: only a file's owner (or the folder's) may replace it. */
    private static final int STICKY = 01000;

    private OutputFile() {
    }

    /**
     * Checks {@code output} against what it must never be (one of the {@code inputs}: the scene,
     * the config) and what would fail only at the end, and makes its temporary file. What depends
     * on the image's size, known once the scene is read, is {@link #checkSize}'s.
     *
     * @param inputs the files the output may not be: the scene, then the config (if any)
     * @return the temporary file beside the output, empty
     */
    static PartFile prepare(Path output, List<Path> inputs) throws StillRefused {
        if (!ImageWriter.isSupported(output)) {
            throw refused("expected a file ending in .png or .pfm, got " + InputException.quotePath(output));
        }
        BasicFileAttributes existing = attributes(output);
        if (existing != null && existing.isDirectory()) {
            throw refused(InputException.quotePath(output) + " is a folder; expected an image file name such as out.png");
        }
        if (existing != null && !existing.isRegularFile()) {
            throw refused(InputException.quotePath(output)
                    + " is not a regular file (a pipe or device); expected an image file name such as out.png");
        }
        Path folder = output.toAbsolutePath().getParent();
        if (folder != null && !Files.isDirectory(folder)) {
            throw refused("no such folder " + InputException.quotePath(folder));
        }
        if (existing != null) {
            for (Path input : inputs) {
                if (sameFile(output, input)) {
                    throw refused(InputException.quotePath(output) + " is the " + (input == inputs.get(0) ? "scene" : "config")
                            + " file " + InputException.quotePath(input)
                            + "; writing the image there would destroy it (choose another output name)");
                }
            }
            if (!Files.isWritable(output)) {
                throw refused(InputException.quotePath(output) + (ownedByAnother(output)
                        ? " belongs to another user and is not writable for this one; choose another output name"
                        : " is read-only; make it writable (chmod u+w) or choose another output name"));
            }
        }
        PartFile temp;
        try {
            temp = PartFile.beside(output);
        } catch (IOException e) {
            throw refused("cannot write " + InputException.quotePath(output) + ": " + reason(e));
        }
        try {
            if (existing != null) {
                checkReplaceable(output, folder, temp.path());
            }
            return temp;
        } catch (StillRefused | RuntimeException e) {
            temp.close();
            throw e;
        }
    }

    /**
     * In a sticky folder (mode 1777, such as /tmp) only the owner of a file, the owner of the folder
     * or root may rename over it; anyone else would find out only at the end. The temporary file,
     * just made, tells who this process is.
     */
    private static void checkReplaceable(Path output, Path folder, Path temp) throws StillRefused {
        try {
            int mode = (Integer) Files.getAttribute(folder, "unix:mode");
            if ((mode & STICKY) == 0) {
                return;
            }
            int me = (Integer) Files.getAttribute(temp, "unix:uid");
            int owner = (Integer) Files.getAttribute(output, "unix:uid", LinkOption.NOFOLLOW_LINKS); // a link's own
            int folderOwner = (Integer) Files.getAttribute(folder, "unix:uid");
            if (me != 0 && me != owner && me != folderOwner) {
                throw refused(InputException.quotePath(output) + " belongs to another user, in a folder where only a file's "
                        + "owner may replace it (sticky, like /tmp); choose another output name");
            }
        } catch (UnsupportedOperationException | IllegalArgumentException | IOException e) {
            // no unix attributes here: the rename decides, and its failure keeps the old file
        }
    }

    /** Whether the file's owner is not the user this program runs as (by name; false when unknown). */
    private static boolean ownedByAnother(Path file) {
        try {
            return !Files.getOwner(file).getName().equals(System.getProperty("user.name"));
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return false;
        }
    }

    /**
     * Keeps the permissions of an image being replaced, as the shell's {@code >} does (a file of
     * mode 640 stays 640).
     */
    static void keepPermissions(Path output, Path temp) {
        try {
            PosixFileAttributes old = Files.readAttributes(output, PosixFileAttributes.class);
            Files.setPosixFilePermissions(temp, old.permissions());
        } catch (IOException | UnsupportedOperationException e) {
            // a new file, or no POSIX permissions: the folder's defaults
        }
    }

    /**
     * The largest file this process may write (its soft {@code ulimit -f}, from a file in the form of
     * Linux's /proc/self/limits), or Long.MAX_VALUE when unlimited or unknown. A larger write fails
     * only when it gets there ({@code File too large}).
     */
    static long fileSizeLimit(Path limits) {
        try {
            for (String line : Files.readAllLines(limits)) {
                if (line.startsWith("Max file size")) {
                    String soft = line.substring("Max file size".length()).trim().split("\\s+")[0];
                    return soft.equals("unlimited") ? Long.MAX_VALUE : Long.parseLong(soft);
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux, or a form not known: no limit is assumed
        }
        return Long.MAX_VALUE;
    }

    /** Whether two names are one file: through a symlink, a hard link, {@code ..}, another case. */
    private static boolean sameFile(Path a, Path b) {
        try {
            return b != null && Files.exists(b) && Files.isSameFile(a, b);
        } catch (IOException | SecurityException e) {
            return false;
        }
    }

    /** The output's attributes (following a symlink), or null when there is no such file. */
    private static BasicFileAttributes attributes(Path output) throws StillRefused {
        try {
            return Files.readAttributes(output, BasicFileAttributes.class);
        } catch (NoSuchFileException e) {
            return null; // no file, or a dangling link (which the image replaces)
        } catch (IOException e) {
            throw refused("cannot write " + InputException.quotePath(output) + ": " + reason(e));
        }
    }

    /** Why a file operation failed, in the system's words: {@code Permission denied}, never a Java class name. */
    public static String reason(IOException e) {
        if (e instanceof FileSystemException fs && fs.getReason() != null) {
            return fs.getReason();
        }
        if (e instanceof AccessDeniedException) {
            return "Permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "No such file or directory";
        }
        if (e instanceof java.nio.file.NotDirectoryException) {
            return "Not a directory";
        }
        if (e instanceof java.nio.file.DirectoryNotEmptyException) {
            return "Is a folder";
        }
        if (e instanceof java.nio.file.FileAlreadyExistsException) {
            return "File exists";
        }
        if (e instanceof FileSystemException || e.getMessage() == null) {
            return "the system refused it";
        }
        return e.getMessage();
    }

    private static StillRefused refused(String problem) {
        return new StillRefused(problem, true);
    }
}
