package glint.app;

import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.Charset;
import java.nio.charset.CharsetEncoder;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Text for standard output or error under a locale whose character set cannot carry every character
 * (US-ASCII under {@code LC_ALL=C}): such a character is written as its Unicode code, {@code \u00e9}
 * ({@code \U0001f600} beyond 16 bits), never as a {@code ?} that reads as another name, and the first
 * line that holds one is followed, once a run, by a line on standard error that says so and names the
 * locale. U+FFFD stays {@code ?}: it stands for bytes the locale could not read (a file name typed under
 * {@code LC_ALL=C}), and the messages about those name the locale already, as does a line about a name
 * the locale cannot carry, which needs no note. Under a Unicode locale the stream is written as it is.
 */
final class LocaleWriter extends Writer {

    /** The line that says characters were written as codes. */
    static String note() {
        return "glint: characters the locale (" + FileNames.locale() + ") cannot show are written as \\uXXXX,"
                + " their Unicode code; " + FileNames.FIX;
    }

    private final Writer out;
    private final CharsetEncoder encoder;
    private final AtomicBoolean noted;
    private final PrintWriter noteTo; // null: this stream itself, after the line
    private boolean escapedOnLine;
    private final StringBuilder line = new StringBuilder(); // the line so far, up to MAX_LINE characters

    private LocaleWriter(Writer out, Charset charset, AtomicBoolean noted, PrintWriter noteTo) {
        super(out);
        this.out = out;
        this.encoder = charset.newEncoder();
        this.noted = noted;
        this.noteTo = noteTo;
    }

    /**
     * A writer of {@code stream} in {@code charset}: as it is for a Unicode charset, else escaping what it
     * cannot carry; the note goes to {@code noteTo} (null: into this stream), once for all the streams that
     * share {@code noted}.
     */
    static Writer of(OutputStream stream, Charset charset, AtomicBoolean noted, PrintWriter noteTo) {
        Writer plain = new OutputStreamWriter(stream, charset);
        return carriesEverything(charset) ? plain : new LocaleWriter(plain, charset, noted, noteTo);
    }

    /** Standard error, as {@link #of} writes it in the locale's charset. */
    static PrintWriter standardError(AtomicBoolean noted) {
        Charset charset = Charset.defaultCharset();
        return carriesEverything(charset) ? new PrintWriter(System.err, true)
                : new PrintWriter(of(System.err, charset, noted, null), true);
    }

    private static boolean carriesEverything(Charset charset) {
        return charset.name().startsWith("UTF-");
    }

    @Override
    public void write(char[] text, int offset, int length) throws IOException {
        synchronized (lock) {
            int end = offset + length;
            for (int i = offset; i < end; i++) {
                boolean pair = Character.isHighSurrogate(text[i]) && i + 1 < end && Character.isLowSurrogate(text[i + 1]);
                put(new String(text, i, pair ? 2 : 1));
                if (pair) {
                    i++;
                } else if (text[i] == '\n') {
                    lineEnded();
                }
            }
        }
    }

    private void put(String character) throws IOException {
        if (line.length() < Main.MAX_LINE) {
            line.append(character);
        }
        if (encoder.canEncode(character)) {
            out.write(character);
        } else if (character.equals("\uFFFD")) {
            out.write('?');
        } else {
            out.write(escape(character));
            escapedOnLine = true;
        }
    }

    /** {@code \u00e9}, or {@code \U0001f600} for a character beyond 16 bits. */
    static String escape(String character) {
        int c = character.codePointAt(0);
        return c > 0xFFFF ? String.format("\\U%08x", c) : String.format("\\u%04x", c);
    }

    private void lineEnded() throws IOException {
        // a line that names the locale and its fix already (a file name it cannot carry) says it all
        boolean saysSo = line.toString().strip().endsWith(FileNames.FIX);
        line.setLength(0);
        if (escapedOnLine && !saysSo && noted.compareAndSet(false, true)) {
            if (noteTo == null) {
                out.write(note() + "\n");
            } else {
                out.flush();
                noteTo.println(note());
            }
        }
        escapedOnLine = false;
    }

    @Override
    public void flush() throws IOException {
        out.flush();
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}
