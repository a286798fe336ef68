package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What a first run outside the repository, or on a machine without a display, is told: the real
 * program in a JVM of its own, started in a folder of the test's.
 */
class FirstRunMessagesTest {

    private static final String SCENE = """
            lights: [{type: point, position: [-3, 5, -4], intensity: 50}]
            objects: [{type: sphere, center: [0, 1, -1], radius: 1}]
            """;

    @TempDir
    Path dir;

    private Child.Result runIn(Path folder, List<String> jvmOptions, String... args) throws Exception {
        List<String> command = new java.util.ArrayList<>(Child.java(jvmOptions.toArray(String[]::new)));
        command.addAll(List.of(args));
        return Child.sh(folder, Child.line(command) + "\n", Map.of());
    }

    @Test
    void aFolderWithoutAConfigSaysWhereTheDefaultSceneWasLookedFor() throws Exception {
        Child.Result r = runIn(dir, List.of(), "--output", "out.png");
        assertEquals(Main.BAD_INPUT, r.status(), r.err());
        assertEquals("glint: no such scene file 'scenes/default.yaml': there is no ./config.properties in the current "
                + "folder (" + dir.toRealPath() + "), so the default scene is looked up from there; name a scene with "
                + "--scene FILE (or a config with --config FILE)\n", r.err());
        assertEquals("", r.out());
        assertFalse(Files.exists(dir.resolve("out.png")));
    }

    @Test
    void theWindowWithoutAConfigSaysTheSameBeforeAnyDisplayIsLookedFor() throws Exception {
        Child.Result r = runIn(dir, List.of("-Djava.awt.headless=true"));
        assertEquals(Main.BAD_INPUT, r.status(), r.err());
        assertEquals("glint: no such scene file 'scenes/default.yaml': there is no ./config.properties in the current "
                + "folder (" + dir.toRealPath() + "), so the default scene is looked up from there; name a scene with "
                + "--scene FILE (or a config with --config FILE)\n", r.err());
    }

    @Test
    void aMissingSceneWithoutADisplayIsTheMissingFileWithTheNameMeant() throws Exception {
        Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(dir.resolve("scenes/default.yaml"), SCENE);
        Child.Result r = runIn(dir, List.of("-Djava.awt.headless=true"), "--scene", "scenes/Default.yaml");
        assertEquals(Main.BAD_INPUT, r.status(), r.err());
        assertEquals("scenes/Default.yaml: no such file (did you mean 'scenes/default.yaml'?)\n", r.err());
    }

    @Test
    void aBrokenSceneWithoutADisplayIsTheSceneError() throws Exception {
        Files.writeString(dir.resolve("broken.yaml"), "objects:\n  - {type: sphere, radus: 1}\n");
        Child.Result r = runIn(dir, List.of("-Djava.awt.headless=true"), "--scene", "broken.yaml");
        assertEquals(Main.BAD_INPUT, r.status(), r.err());
        assertEquals("broken.yaml:2:20: unknown key 'radus' in sphere (did you mean 'radius'?)\n", r.err());
    }

    @Test
    void aGoodSceneWithoutADisplayIsTheOneLineAboutTheDisplay() throws Exception {
        Files.writeString(dir.resolve("good.yaml"), SCENE);
        Child.Result r = runIn(dir, List.of("-Djava.awt.headless=true"), "--scene", "good.yaml");
        assertEquals(Main.FAILURE, r.status(), r.err());
        assertEquals("glint: no display available for the window; render a still with --output FILE.png (for example: "
                + "java -jar target/glint.jar --output out.png)\n", r.err());
    }
}
