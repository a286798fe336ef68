package glint.input;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Locale;

/**
 * Reads the text files a user names (scene, config): only a regular file (never a FIFO, device or
 * socket, whose reads can block for ever or never end), never more than a bound, strictly UTF-8, and
 * every failure an {@link InputException} that says why and, where it can, where.
 */
public final class TextFiles {

    private TextFiles() {
    }

    /** What a file is, read without opening it (a FIFO is never opened); null when it is a regular file. */
    public static String notARegularFile(Path path) throws IOException {
        BasicFileAttributes attributes = Files.readAttributes(path, BasicFileAttributes.class);
        if (attributes.isRegularFile()) {
            return null;
        }
        if (attributes.isDirectory()) {
            return "is a folder, not a file";
        }
        return "is not a regular file (a pipe, device or socket); expected a file on disk";
    }

    /**
     * The bytes of a regular file of at most {@code maxBytes}; larger files are refused by their size
     * before reading, and a file that grows while read is cut off at the bound and refused.
     *
     * @param tooBig the message for a file above the bound, given its size
     */
    public static byte[] readBounded(Path path, long maxBytes, java.util.function.LongFunction<String> tooBig)
            throws InputException {
        String name = path.toString();
        try {
            String special = notARegularFile(path);
            if (special != null) {
                throw new InputException(name, 0, 0, special);
            }
            long size = Files.size(path);
            if (size > maxBytes) {
                throw new InputException(name, 0, 0, tooBig.apply(size));
            }
            int bound = (int) Math.min(Integer.MAX_VALUE - 16, maxBytes + 1);
            byte[] bytes;
            try (InputStream in = Files.newInputStream(path)) {
                bytes = in.readNBytes(bound);
            }
            if (bytes.length > maxBytes) {
                throw new InputException(name, 0, 0, tooBig.apply(bytes.length));
            }
            return bytes;
        } catch (IOException e) {
            throw unreadable(name, e);
        }
    }

    /** The most entries of a folder looked through for a file name like a missing one. */
    static final int MAX_FOLDER_ENTRIES = 10_000;

    /**
     * {@code " (did you mean 'scenes/default.yaml'?)"} when the folder of a missing file holds a file of a
     * name close to its own (another case, a letter off), otherwise empty.
     */
    static String similarFile(String name) {
        Path path;
        try {
            path = Path.of(name);
        } catch (java.nio.file.InvalidPathException e) {
            return "";
        }
        Path fileName = path.getFileName();
        Path folder = path.getParent() != null ? path.getParent() : Path.of("");
        if (fileName == null) {
            return "";
        }
        java.util.List<String> names = new java.util.ArrayList<>();
        try (java.util.stream.Stream<Path> entries = Files.list(folder.toString().isEmpty() ? Path.of(".") : folder)) {
            entries.limit(MAX_FOLDER_ENTRIES).filter(Files::isRegularFile)
                    .forEach(entry -> names.add(entry.getFileName().toString()));
        } catch (IOException | RuntimeException e) {
            return ""; // no folder, or one that cannot be listed: nothing to suggest
        }
        String best = closestFileName(fileName.toString(), names);
        return best == null ? "" : " (did you mean " + InputException.quotePath(folder.resolve(best)) + "?)";
    }

    /**
     * The name among {@code names} that is {@code given} mistyped: the same ending (.yaml, or .yml for it), and the rest
     * at most 2 edits away (ignoring case) and less than half of it; null when none is.
     */
    static String closestFileName(String given, java.util.List<String> names) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        String stem = stem(given).toLowerCase(Locale.ROOT);
        for (String name : names) {
            if (!sameKind(extension(name), extension(given)) || given.length() > 255) {
                continue;
            }
            int d = Suggestions.distance(stem, stem(name).toLowerCase(Locale.ROOT));
            if (d < bestDistance && d <= 2 && 2 * d < stem.length()) {
                bestDistance = d;
                best = name;
            }
        }
        return best;
    }

    private static String stem(String name) {
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(0, dot) : name;
    }

    /** Whether two endings name the same kind of file: equal but for case, or .yaml and .yml. */
    private static boolean sameKind(String a, String b) {
        return a.equalsIgnoreCase(b) || isYaml(a) && isYaml(b);
    }

    private static boolean isYaml(String extension) {
        return extension.equalsIgnoreCase(".yaml") || extension.equalsIgnoreCase(".yml");
    }

    private static String extension(String name) {
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(dot) : "";
    }

    /** Why a file could not be read, in words ("no such file", "permission denied", ...). */
    public static InputException unreadable(String name, IOException e) {
        if (e instanceof NoSuchFileException) {
            return new InputException(name, 0, 0, "no such file" + similarFile(name));
        }
        if (e instanceof AccessDeniedException) {
            return new InputException(name, 0, 0, "cannot read: permission denied");
        }
        if (e instanceof FileSystemException fs && fs.getReason() != null) {
            return new InputException(name, 0, 0, "cannot read: " + fs.getReason());
        }
        return new InputException(name, 0, 0, "cannot read: " + e.getMessage());
    }

    /**
     * The bytes as UTF-8 text, or an error at the line and column of the first byte that is not UTF-8
     * text or of the first control character (other than tab and line breaks), with a hint when the
     * file looks like UTF-16.
     */
    public static String utf8(String name, byte[] bytes) throws InputException {
        if (looksLikeUtf32(bytes)) { // before UTF-16: UTF-32's byte-order mark begins with UTF-16's
            throw new InputException(name, 1, 1, "not UTF-8 text: the file looks like UTF-32 (save it as UTF-8)");
        }
        if (looksLikeUtf16(bytes)) {
            throw new InputException(name, 1, 1, "not UTF-8 text: the file looks like UTF-16 (save it as UTF-8)");
        }
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length);
        CoderResult result = decoder.decode(in, out, true);
        if (!result.isError()) {
            decoder.flush(out);
        }
        out.flip();
        String text = out.toString(); // all of it, or the part before the first byte that is not UTF-8
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || (c >= 0x7f && c < 0xa0 && c != 0x85)
                    || c == 0xfffe || c == 0xffff) {
                int[] at = position(text, i);
                throw new InputException(name, at[0], at[1], String.format(Locale.ROOT,
                        "not a text file: control character U+%04X (only tab and line breaks are allowed)", (int) c));
            }
        }
        if (result.isError()) {
            int[] at = position(text, text.length());
            throw new InputException(name, at[0], at[1], String.format(Locale.ROOT,
                    "not UTF-8 text: byte 0x%02X cannot stand here in UTF-8 (save the file as UTF-8)",
                    bytes[in.position()] & 0xff));
        }
        return text;
    }

    /**
     * Four-byte text: its first characters (up to 16) each four bytes, two of them NUL on the same side,
     * as in a UTF-32 byte-order mark ({@code 00 00 FE FF}, {@code FF FE 00 00}) and every character
     * below U+10000. UTF-8 text has no NUL, and UTF-16 no two in a row in its first characters.
     */
    private static boolean looksLikeUtf32(byte[] b) {
        int units = Math.min(16, b.length / 4);
        boolean bigEndian = units > 0, littleEndian = units > 0;
        for (int i = 0; i < 4 * units; i += 4) {
            boolean highZero = b[i] == 0 && b[i + 1] == 0, lowZero = b[i + 2] == 0 && b[i + 3] == 0;
            bigEndian &= highZero && !lowZero;
            littleEndian &= lowZero && !highZero;
        }
        return bigEndian || littleEndian;
    }

    /** Two-byte text: a UTF-16 byte-order mark, or a NUL in one of the first two bytes. */
    private static boolean looksLikeUtf16(byte[] b) {
        if (b.length >= 2 && ((b[0] == (byte) 0xFE && b[1] == (byte) 0xFF) || (b[0] == (byte) 0xFF && b[1] == (byte) 0xFE))) {
            return true;
        }
        return b.length >= 4 && (b[0] == 0) != (b[1] == 0) && (b[2] == 0) != (b[3] == 0) && (b[0] == 0) == (b[2] == 0);
    }

    /** Line and column (from 1, in characters) of index {@code end} of the text. */
    private static int[] position(CharSequence text, int end) {
        int line = 1, column = 1;
        for (int i = 0; i < end; i++) {
            if (text.charAt(i) == '\n') {
                line++;
                column = 1;
            } else if (!Character.isLowSurrogate(text.charAt(i))) {
                column++;
            }
        }
        return new int[] {line, column};
    }

    /**
     * An error at the first line longer than {@code maxChars} characters (code points), or null. Very long lines
     * make the YAML reader slow (its time grows with the square of a line's length).
     */
    public static InputException lineTooLong(String name, String text, int maxChars) {
        int line = 1, length = 0; // in characters (code points): an emoji is one
        for (int i = 0; i <= text.length(); i++) {
            if (i == text.length() || text.charAt(i) == '\n') {
                if (length > maxChars) {
                    return new InputException(name, line, maxChars + 1, String.format(Locale.ROOT,
                            "line %d is %,d characters long; the longest line accepted is %,d (break it into shorter lines)",
                            line, length, maxChars));
                }
                line++;
                length = 0;
            } else if (!Character.isLowSurrogate(text.charAt(i))) {
                length++;
            }
        }
        return null;
    }

    /**
     * "the file is S; the largest ... is M": both sizes as {@link #size}, or in bytes when they would
     * read the same.
     */
    public static String fileIsLargerThan(long size, long max, String largest) {
        String[] sizes = sizes(size, max);
        return "the file is " + sizes[0] + "; " + largest + " is " + sizes[1];
    }

    /** Two sizes for a message that compares them: as {@link #size}, or in bytes when they would read the same. */
    public static String[] sizes(long a, long b) {
        boolean same = size(a).equals(size(b));
        return same ? new String[] {String.format(Locale.ROOT, "%,d bytes", a), String.format(Locale.ROOT, "%,d bytes", b)}
                : new String[] {size(a), size(b)};
    }

    /** A size for messages: "512 bytes", "12.5 KB", "8.0 MB" (1 KB = 1024 bytes). */
    public static String size(long bytes) {
        if (bytes < 1024) {
            return bytes + (bytes == 1 ? " byte" : " bytes");
        }
        if (bytes < 1024 * 1024) {
            return String.format(Locale.ROOT, "%.1f KB", bytes / 1024.0);
        }
        return String.format(Locale.ROOT, "%.1f MB", bytes / 1048576.0);
    }
}
