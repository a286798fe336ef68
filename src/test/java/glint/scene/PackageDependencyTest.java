package glint.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The dependency direction of docs/architecture.md, read from the imports of the main sources: the
 * scene model is plain data, the registry sits above it and below the reader and the renderer.
 */
class PackageDependencyTest {

    private static final Pattern GLINT_IMPORT = Pattern.compile("^import (?:static )?glint\\.(\\w+)\\.", Pattern.MULTILINE);

    @Test
    void theSceneModelImportsOnlyTheMathOfGlint() throws IOException {
        assertEquals(Set.of("math"), glintPackagesImportedBy("scene"));
    }

    @Test
    void theRegistryImportsTheModelAndWhatItCompilesToButNeitherTheReaderNorTheRenderer() throws IOException {
        Set<String> imported = glintPackagesImportedBy("registry");
        assertTrue(Set.of("scene", "geometry", "shading", "input", "math").containsAll(imported), imported.toString());
        assertTrue(imported.containsAll(List.of("scene", "geometry", "shading")), imported.toString());
    }

    @Test
    void theSceneFileReaderImportsTheModelAndTheRegistryButNotTheRenderer() throws IOException {
        Set<String> imported = glintPackagesImportedBy("scenefile");
        assertTrue(Set.of("scene", "registry", "input", "math").containsAll(imported), imported.toString());
        assertTrue(imported.containsAll(List.of("scene", "registry")), imported.toString());
    }

    /** The glint packages the main sources of {@code glint.<name>} import, besides their own. */
    private static Set<String> glintPackagesImportedBy(String name) throws IOException {
        Set<String> packages = new TreeSet<>();
        try (Stream<Path> files = Files.list(Path.of("src/main/java/glint", name))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                Matcher m = GLINT_IMPORT.matcher(Files.readString(file));
                while (m.find()) {
                    packages.add(m.group(1));
                }
            }
        }
        packages.remove(name);
        return packages;
    }
}
