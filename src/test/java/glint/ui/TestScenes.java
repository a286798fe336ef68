package glint.ui;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;

/** Small scenes for the window tests. */
public final class TestScenes {

    private TestScenes() {
    }

    /** A red sphere on a grey floor, camera at (0, 1, -4) looking along +z, the given background. */
    public static String sphere(double r, double g, double b) {
        return String.format(Locale.ROOT, """
                camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
                background: [%s, %s, %s]
                lights:
                  - {type: point, position: [-3, 5, -4], intensity: 50}
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: matte, color: [0.8, 0.2, 0.2]}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                """, r, g, b);
    }

    /** Replaces a file's content at once (as editors do: write aside, then rename over it). */
    public static void replace(Path file, String text) throws IOException {
        Path aside = file.resolveSibling(file.getFileName() + ".tmp");
        Files.writeString(aside, text, StandardCharsets.UTF_8);
        Files.move(aside, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }
}
