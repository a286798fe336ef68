package glint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The package map of docs/architecture.md, read from the imports of the main sources: the packages
 * form layers, and each imports only packages of the layers below it, so that data flows one way
 * (files, the scene model, compiled render data, frames, images, the window and the command line).
 */
class PackageLayersTest {

    /** Bottom to top; a package may import only those before it. */
    static final List<String> LAYERS = List.of(
            "math", "scene", "input", "geometry", "image", "shading", "accel", "registry", "render", "scenefile",
            "config", "still",
            "ui.input", "ui.frames", "ui.screen", "ui.view", "ui.scenes", "ui.capture", "ui.engine", "ui.swing",
            "app");

    private static final Path MAIN = Path.of("src/main/java/glint");
    private static final Pattern GLINT_IMPORT =
            Pattern.compile("^import (?:static )?glint\\.((?:[a-z]\\w*\\.)*?[a-z]\\w*)\\.[A-Z]", Pattern.MULTILINE);

    @Test
    void everyPackageImportsOnlyTheLayersBelowIt() throws IOException {
        List<String> crossings = new ArrayList<>();
        imports().forEach((pkg, imported) -> {
            int layer = LAYERS.indexOf(pkg);
            for (String other : imported) {
                if (LAYERS.indexOf(other) >= layer) {
                    crossings.add("glint." + pkg + " imports glint." + other);
                }
            }
        });
        assertEquals(List.of(), crossings);
    }

    @Test
    void everyPackageWithCodeHasItsLayer() throws IOException {
        assertEquals(new TreeSet<>(LAYERS), new TreeSet<>(imports().keySet()));
    }

    @Test
    void theSceneModelIsPlainDataThatImportsOnlyTheMath() throws IOException {
        assertEquals(Set.of("math"), imports().get("scene"));
    }

    @Test
    void onlyTheWindowsSwingPackageUsesSwing() throws IOException {
        try (Stream<Path> files = Files.walk(MAIN)) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                if (Files.readString(file).contains("\nimport javax.swing.")) {
                    assertTrue(file.startsWith(MAIN.resolve("ui/swing")), file.toString());
                }
            }
        }
    }

    /** Each package with classes (a name below {@code glint}) and the glint packages it imports. */
    private static Map<String, Set<String>> imports() throws IOException {
        Map<String, Set<String>> imports = new TreeMap<>();
        try (Stream<Path> files = Files.walk(MAIN)) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                if (file.getFileName().toString().equals("package-info.java")) {
                    continue;
                }
                String pkg = MAIN.relativize(file.getParent()).toString().replace('/', '.');
                Set<String> imported = imports.computeIfAbsent(pkg, p -> new TreeSet<>());
                Matcher m = GLINT_IMPORT.matcher(Files.readString(file));
                while (m.find()) {
                    if (!m.group(1).equals(pkg)) {
                        imported.add(m.group(1));
                    }
                }
            }
        }
        return imports;
    }
}
