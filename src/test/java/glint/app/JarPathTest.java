package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The commands the program suggests name the jar it really runs from: a jar of the program, put
 * in a folder of another name (with a space), started with {@code java -jar} in a child process.
 */
class JarPathTest {

    @TempDir
    Path dir;

    private Path jar;

    /** {@code dir/my jars/glint-1.jar}: the program's classes, its libraries beside it on the manifest's Class-Path. */
    @BeforeEach
    void buildAJar() throws Exception {
        Path folder = Files.createDirectory(dir.resolve("my jars"));
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Files.copy(codeSource(picocli.CommandLine.class), folder.resolve("picocli.jar"));
        Files.copy(codeSource(org.snakeyaml.engine.v2.api.LoadSettings.class), folder.resolve("snakeyaml.jar"));
        Manifest manifest = new Manifest();
        manifest.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        manifest.getMainAttributes().put(Attributes.Name.MAIN_CLASS, "glint.app.Main");
        manifest.getMainAttributes().put(Attributes.Name.CLASS_PATH, "picocli.jar snakeyaml.jar");
        jar = folder.resolve("glint-1.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar), manifest);
             Stream<Path> files = Files.walk(classes)) {
            for (Path file : files.filter(Files::isRegularFile).toList()) {
                out.putNextEntry(new JarEntry(classes.relativize(file).toString().replace('\\', '/')));
                Files.copy(file, (OutputStream) out);
                out.closeEntry();
            }
        }
        Files.writeString(dir.resolve("empty.properties"), "");
    }

    private static Path codeSource(Class<?> c) throws Exception {
        return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    private Child.Result run(Path workingFolder, String jarAsTyped, String... args) throws IOException, InterruptedException {
        List<String> command = new java.util.ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-XX:-UsePerfData", "-jar", jarAsTyped));
        command.addAll(List.of(args));
        return Child.sh(workingFolder, Child.line(command) + "\n", Map.of());
    }

    @Test
    void theTryHelpHintNamesTheJarAsItCanBeTypedAgain() throws Exception {
        // from the folder above the jar's: relative to it, in quotes for the space
        Child.Result r = run(dir, "my jars/glint-1.jar", "--bogus");
        assertEquals(2, r.status(), r.err());
        assertEquals(List.of("glint: unknown option '--bogus'",
                "Try 'java -jar \"my jars/glint-1.jar\" --help' for the options."), r.err().lines().toList());
        // from elsewhere: the absolute path
        Path elsewhere = Files.createDirectory(dir.resolve("elsewhere"));
        r = run(elsewhere, jar.toString(), "--width", "x");
        assertEquals(2, r.status(), r.err());
        assertEquals("Try 'java -jar \"" + jar + "\" --help' for the options.", r.err().lines().toList().get(1));
    }

    @Test
    void theHelpsExamplesNameTheJar() throws Exception {
        Child.Result r = run(dir, "my jars/glint-1.jar", "--help");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("\n    java -jar \"my jars/glint-1.jar\" --scene scenes/glass.yaml\n"), r.out());
        assertTrue(!r.out().contains("target/glint.jar"), r.out());
    }
}
