package glint.study;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Rewrites the generated part of a hand-written markdown file: the text between
 * {@code <!-- generated:NAME -->} and {@code <!-- /generated:NAME -->}. A file without the markers
 * gets them, with the section, at its end; a missing file is created.
 */
public final class GeneratedSection {

    private GeneratedSection() {
    }

    public static void write(Path file, String name, String body) throws IOException {
        String open = "<!-- generated:" + name + " -->";
        String close = "<!-- /generated:" + name + " -->";
        String text = Files.isRegularFile(file) ? Files.readString(file, StandardCharsets.UTF_8) : "";
        String section = open + "\n" + body.strip() + "\n" + close;
        int start = text.indexOf(open);
        int end = text.indexOf(close);
        String updated;
        if (start >= 0 && end > start) {
            updated = text.substring(0, start) + section + text.substring(end + close.length());
        } else {
            updated = text + (text.isEmpty() || text.endsWith("\n") ? "" : "\n") + "\n" + section + "\n";
        }
        if (file.getParent() != null) {
            Files.createDirectories(file.getParent());
        }
        Files.writeString(file, updated, StandardCharsets.UTF_8);
    }
}
