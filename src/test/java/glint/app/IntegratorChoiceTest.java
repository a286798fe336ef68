package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Choosing the integrator: {@code integrator} in config.properties, in a scene's {@code render:}
 * block and {@code --integrator}, ranked like every other setting, with positioned errors; the path
 * integrator refused beside the phong model wherever the two meet.
 */
class IntegratorChoiceTest {

    @TempDir
    Path dir;

    private record Result(int status, String out, String err) {
        String firstErrLine() {
            return err.lines().findFirst().orElse("");
        }
    }

    private static Result run(String... args) {
        StringWriter out = new StringWriter(), err = new StringWriter();
        int status = Main.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
        return new Result(status, out.toString(), err.toString());
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    private static final String SCENE = """
            lights: [{type: point, position: [0, 4, -2], intensity: 20}]
            objects: [{type: sphere, center: [0, 1, 0], radius: 1}]
            """;

    private Result still(String config, String scene, String... flags) throws IOException {
        Path c = write("config.properties", config), s = write("s.yaml", scene);
        String[] args = {"--config", c.toString(), "--scene", s.toString(), "--width", "8", "--height", "6",
                "--spp", "1", "--output", dir.resolve("o.png").toString()};
        String[] all = new String[args.length + flags.length];
        System.arraycopy(args, 0, all, 0, args.length);
        System.arraycopy(flags, 0, all, args.length, flags.length);
        return run(all);
    }

    @Test
    void theFlagTheBlockAndTheConfigRankAsEverySettingDoes() throws IOException {
        Result config = still("integrator=path\n", SCENE);
        assertEquals(0, config.status(), config.err());
        assertTrue(config.out().contains("cook-torrance, path, depth 16)"), config.out());
        Result block = still("integrator=whitted\n", SCENE + "render: {integrator: path}\n");
        assertTrue(block.out().contains(", path, depth"), block.out());
        Result flag = still("integrator=path\n", SCENE + "render: {integrator: path}\n", "--integrator", "whitted");
        assertTrue(flag.out().contains("cook-torrance, depth 16)"), "Whitted is not named: " + flag.out());
        assertFalse(flag.out().contains("path"), flag.out());
    }

    @Test
    void anUnknownIntegratorIsAnErrorWithASuggestionWhereverItIsNamed() throws IOException {
        Result flag = still("", SCENE, "--integrator", "paht");
        assertEquals(2, flag.status());
        assertEquals("glint: --integrator: unknown integrator 'paht', expected whitted, path or bdpt (did you mean 'path'?)",
                flag.firstErrLine());
        Result config = still("threads=1\nintegrator = witted\n", SCENE);
        assertEquals(2, config.status());
        assertEquals(dir.resolve("config.properties") + ":2:1: integrator: unknown integrator 'witted', expected "
                + "whitted, path or bdpt (did you mean 'whitted'?)", config.firstErrLine());
        Result block = still("", SCENE + "render:\n  integrator: bidirectional\n");
        assertEquals(2, block.status());
        assertEquals(dir.resolve("s.yaml") + ":4:15: unknown integrator 'bidirectional', expected whitted, path or"
                + " bdpt (expected one of: whitted, path, bdpt)", block.firstErrLine());
    }

    @Test
    void thePathIntegratorIsRefusedBesideThePhongModel() throws IOException {
        String why = "the path and bdpt integrators need shading cook-torrance: phong's coefficients are not a BSDF a path"
                + " can sample (use --integrator whitted with phong)";
        Result flags = still("", SCENE, "--integrator", "path", "--shading", "phong");
        assertEquals(2, flags.status());
        assertEquals("glint: --integrator path: " + why, flags.firstErrLine());
        Result shadingFlag = still("integrator=path\n", SCENE, "--shading", "phong");
        assertEquals("glint: --shading phong: " + why, shadingFlag.firstErrLine());
        Result config = still("shading=phong\nintegrator=path\n", SCENE);
        assertEquals(2, config.status());
        assertEquals(dir.resolve("config.properties") + ":2:1: " + why, config.firstErrLine());
        Result block = still("shading=phong\n", SCENE + "render: {integrator: path}\n");
        assertEquals(2, block.status());
        assertEquals(dir.resolve("s.yaml") + ":3:22: render: " + why, block.firstErrLine());
        Result mended = still("shading=phong\n", SCENE + "render: {integrator: path}\n", "--shading", "cook-torrance");
        assertEquals(0, mended.status(), mended.err());
    }
}
