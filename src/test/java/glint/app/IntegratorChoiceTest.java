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

    /**
     * The path integrator and phong do not go together: set at the same rank they are an error; set at two
     * ranks, the higher one (flag, then render: block, then config) wins and the other yields with one note.
     */
    @Test
    void thePathIntegratorBesideThePhongModelIsAnErrorOnlyWhereBothHaveTheSameRank() throws IOException {
        String why = "the path and bdpt integrators need shading cook-torrance: phong's coefficients are not a BSDF a path"
                + " can sample (use --integrator whitted with phong)";
        Result flags = still("", SCENE, "--integrator", "path", "--shading", "phong");
        assertEquals(2, flags.status());
        assertEquals("glint: --integrator path: " + why, flags.firstErrLine());
        Result config = still("shading=phong\nintegrator=path\n", SCENE);
        assertEquals(2, config.status());
        assertEquals(dir.resolve("config.properties") + ":2:1: " + why, config.firstErrLine());
        Result block = still("", SCENE + "render: {integrator: path, shading: phong}\n");
        assertEquals(2, block.status());
        assertEquals(dir.resolve("s.yaml") + ":3:22: render: " + why, block.firstErrLine());

        Result shadingFlag = still("integrator=path\n", SCENE, "--shading", "phong");
        assertEquals(0, shadingFlag.status(), shadingFlag.err());
        assertEquals("glint: note: the config's integrator path yields to --shading phong (the path integrator needs "
                + "cook-torrance); rendering with whitted\n", shadingFlag.err());
        assertTrue(shadingFlag.out().contains(", phong, depth 16)"), shadingFlag.out());
        Result overConfig = still("shading=phong\n", SCENE + "render: {integrator: path}\n");
        assertEquals(0, overConfig.status(), overConfig.err());
        assertEquals("glint: note: the config's shading phong yields to render: integrator path (the path integrator "
                + "needs cook-torrance); rendering with cook-torrance\n", overConfig.err());
        Result mended = still("shading=phong\n", SCENE + "render: {integrator: path}\n", "--shading", "cook-torrance");
        assertEquals(0, mended.status(), mended.err());
        assertEquals("", mended.err());
    }

    /** The shipped phong scene asks for phong in its block; --integrator path outranks it. */
    @Test
    void aFlagOutranksTheBlocksConflictingSettingWithOneNote() throws IOException {
        Result r = still("", "render: {shading: phong}\n" + SCENE, "--integrator", "path");
        assertEquals(0, r.status(), r.err());
        assertEquals(dir.resolve("s.yaml") + ":1:19: note: render: shading phong yields to --integrator path "
                + "(the path integrator needs cook-torrance); rendering with cook-torrance\n", r.err());
        assertTrue(r.out().contains("cook-torrance, path, depth 16)"), r.out());
    }

    /** A flag is checked against the settings the block gives, not against the bare config. */
    @Test
    void aFlagIsNotRefusedForAConflictTheBlockRemoves() throws IOException {
        Result r = still("shading=phong\n", "render: {shading: cook-torrance}\n" + SCENE, "--integrator", "path");
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
    }
}
