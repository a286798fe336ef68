package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The image never destroys a file the user keeps: an output that is the scene or the config by any
 * name, a read-only image, another user's image in a sticky folder are refused before any work,
 * with one line and status 2; echoed names are cut. The checks run on real files, and where
 * another user is needed, in a real process of that user.
 */
class OutputSafetyTest {

    private static final String SCENE = """
            camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
            objects:
              - {type: sphere, center: [0, 1, 0], radius: 1}
            """;

    @TempDir
    Path dir;
    private Path config;

    private record Result(int status, String out, String err) {
    }

    @BeforeEach
    void emptyConfig() throws IOException {
        config = Files.writeString(dir.resolve("empty.properties"), "");
    }

    private static Result run(String... args) {
        StringWriter out = new StringWriter(), err = new StringWriter();
        int status = Main.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
        return new Result(status, out.toString(), err.toString());
    }

    private Result render(Path scene, String output) {
        return run("--config", config.toString(), "--scene", scene.toString(), "--output", output,
                "--width", "8", "--height", "6", "--spp", "1");
    }

    private List<String> files() throws IOException {
        try (Stream<Path> list = Files.list(dir)) {
            return list.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void anOutputThatIsTheSceneByAnyNameIsRefusedAndTheSceneKept() throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.png"), SCENE); // a YAML scene under an image's name
        Files.createDirectory(dir.resolve("sub"));
        Files.createLink(dir.resolve("hard.png"), scene);
        Files.createSymbolicLink(dir.resolve("link.png"), scene.getFileName());
        for (String output : List.of(scene.toString(), dir + "/./scene.png", dir + "/sub/../scene.png",
                dir.resolve("hard.png").toString(), dir.resolve("link.png").toString(), dir + "/sub/../link.png")) {
            Result r = render(scene, output);
            assertEquals(2, r.status(), output);
            assertEquals("glint: --output: '" + output + "' is the scene file '" + scene
                    + "'; writing the image there would destroy it (choose another output name)\n", r.err());
            assertEquals("", r.out());
            assertEquals(SCENE, Files.readString(scene));
        }
        assertEquals(List.of("empty.properties", "hard.png", "link.png", "scene.png", "sub"), files(), "no temporary file left");
    }

    @Test
    void anOutputThatIsTheConfigIsRefusedAndTheConfigKept() throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), SCENE);
        Path cfg = Files.writeString(dir.resolve("cfg.pfm"), "samples=1\n");
        Result r = run("--config", cfg.toString(), "--scene", scene.toString(), "--output", dir + "/./cfg.pfm");
        assertEquals(2, r.status());
        assertEquals("glint: --output: '" + dir + "/./cfg.pfm' is the config file '" + cfg
                + "'; writing the image there would destroy it (choose another output name)\n", r.err());
        assertEquals("samples=1\n", Files.readString(cfg));
    }

    @Test
    void aReplacedImageKeepsItsPermissions() throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), SCENE);
        Path image = Files.writeString(dir.resolve("out.png"), "old");
        Files.setPosixFilePermissions(image, PosixFilePermissions.fromString("rw-r-----"));
        Result r = render(scene, image.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("rw-r-----", PosixFilePermissions.toString(Files.getPosixFilePermissions(image)));
        assertFalse(Files.readString(image, java.nio.charset.StandardCharsets.ISO_8859_1).equals("old"));
    }

    @Test
    void aLongOutputNameIsCutInTheMessageAndIsBadInput() throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), SCENE);
        String output = dir + "/" + "o".repeat(100_000) + ".png";
        Result r = render(scene, output);
        assertEquals(2, r.status());
        String cut = output.substring(0, 60) + "..." + output.substring(output.length() - 60);
        assertEquals("glint: --output: cannot write '" + cut + "': File name too long\n", r.err());
        assertEquals(List.of("empty.properties", "scene.yaml"), files());
    }

    @Test
    void aLongSceneNameIsCutInTheMessage() {
        String scene = dir + "/" + "s".repeat(100_000) + ".yaml";
        Result r = run("--config", config.toString(), "--scene", scene, "--output", dir.resolve("o.png").toString());
        assertEquals(2, r.status());
        assertEquals(scene.substring(0, 60) + "..." + scene.substring(scene.length() - 60) + ": cannot read: File name too long\n",
                r.err());
    }

    @Test
    void anUnknownLongOptionIsCutInTheMessage() {
        Result r = run("--" + "x".repeat(100_000));
        assertEquals(2, r.status());
        assertEquals("glint: unknown option '--" + "x".repeat(58) + "...'", r.err().lines().findFirst().orElse(""));
    }

    @Test
    void anUnmatchedLongArgumentIsCutInTheMessage() {
        Result r = run("y".repeat(100_000));
        assertEquals(2, r.status());
        assertEquals("glint: unexpected argument '" + "y".repeat(60) + "...' (each value follows its option, as in --spp 4)", r.err().lines().findFirst().orElse(""));
    }

    @Test
    void aConfiguredSceneNameWithANulIsRefusedAtItsLine() throws Exception {
        Path cfg = Files.writeString(dir.resolve("nul.properties"), "samples=1\nscene=a\\u0000b.yaml\n");
        Result r = run("--config", cfg.toString(), "--output", dir.resolve("o.png").toString());
        assertEquals(2, r.status());
        assertEquals(cfg + ":2:1: scene: a file name cannot hold the character NUL, got 'a\\u0000b.yaml'\n", r.err());
    }

    @Test
    void aNameNearTheFoldersLimitIsWritten() throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), SCENE);
        String name = "n".repeat(251) + ".png"; // 255 bytes, the most a name may have: its temporary file's is shorter
        Result r = render(scene, dir.resolve(name).toString());
        assertEquals(0, r.status(), r.err());
        assertEquals(List.of("empty.properties", name, "scene.yaml"), files());
    }

    // ---------------------------------------------------------------- under a file size limit (ulimit -f)

    /**
     * Under {@code ulimit -f}: a PFM, whose size is known, larger than the limit is refused before
     * the work; a PNG, whose size is known only once encoded, fails at the end with the system's
     * reason, the old image kept. Both in a real process that has the limit.
     */
    @Test
    void aFileSizeLimitRefusesAPfmBeforeTheWorkAndAPngAtTheEndKeepingTheOldImage() throws Exception {
        Files.writeString(dir.resolve("scene.yaml"), Files.readString(Path.of("scenes/bench/spec-example.yaml")));
        Files.writeString(dir.resolve("old.pfm"), "old");
        Files.writeString(dir.resolve("old.png"), "old");
        List<String> common = List.of("--config", config.toString(), "--scene", "scene.yaml", "--spp", "1", "--threads", "1");
        String script = "ulimit -f 8\n" // 4 KB or 8 KB, as the shell counts blocks
                + "grep 'Max file size' /proc/self/limits\n"
                + Child.line(concat(Child.java("-XX:-UsePerfData"), common, List.of("--output", "old.pfm", "--width", "200", "--height", "100")))
                + "\necho \"status $?\"\n"
                + Child.line(concat(Child.java("-XX:-UsePerfData"), common, List.of("--output", "old.png", "--width", "320", "--height", "240")))
                + "\necho \"status $?\"\n";
        Child.Result r = Child.sh(dir, script, Map.of());
        List<String> out = r.out().lines().toList();
        long limit = Long.parseLong(out.get(0).substring("Max file size".length()).trim().split("\\s+")[0]);
        assertEquals(List.of("status 2", "status 1"), out.subList(1, 3), r.err());
        // a run that outlasts 2 s on a loaded machine shows its steps too; they are not what is checked here
        String messages = r.err().lines().filter(line -> !line.matches(
                "(reading|preparing) the scene\\.\\.\\.( [0-9]+ s so far)?|(rendering|writing the image): [0-9]+% done, .*"))
                .map(line -> line + "\n").collect(java.util.stream.Collectors.joining());
        assertEquals("glint: --output: a 200x100 PFM is 234.4 KB, more than the largest file this process may write ("
                + glint.input.TextFiles.size(limit) + ", ulimit -f); render a smaller image, a PNG, or raise the limit\n"
                + "glint: cannot write old.png: File too large\n", messages);
        assertEquals("old", Files.readString(dir.resolve("old.pfm")));
        assertEquals("old", Files.readString(dir.resolve("old.png")));
        assertEquals(List.of("empty.properties", "old.pfm", "old.png", "scene.yaml"), files(), "no temporary file left");
    }

    @SafeVarargs
    private static List<String> concat(List<String>... parts) {
        List<String> all = new ArrayList<>();
        for (List<String> part : parts) {
            all.addAll(part);
        }
        return all;
    }

    // ---------------------------------------------------------------- as another user

    @Test
    void aReadOnlyImageIsRefusedBeforeRenderingAsTheShellsRedirectionWould() throws Exception {
        if (!isRoot()) { // this user is refused as it is
            Path scene = Files.writeString(dir.resolve("scene.yaml"), SCENE);
            Path image = Files.writeString(dir.resolve("out.png"), "old");
            Files.setPosixFilePermissions(image, PosixFilePermissions.fromString("r--r--r--"));
            Result r = render(scene, image.toString());
            assertEquals(2, r.status(), r.err());
            assertEquals("glint: --output: '" + image + "' is read-only; make it writable (chmod u+w) or choose another "
                    + "output name\n", r.err());
            assertEquals("old", Files.readString(image));
            return;
        }
        Path shared = sharedFolder(); // root may replace it, as with >: the program runs as user nobody
        Files.writeString(shared.resolve("scene.yaml"), SCENE);
        Files.writeString(shared.resolve("empty.properties"), "");
        Path image = Files.writeString(shared.resolve("out.png"), "old");
        Files.setPosixFilePermissions(image, PosixFilePermissions.fromString("r--r--r--"));
        Files.setOwner(image, Files.getOwner(shared)); // nobody's file, read-only for nobody too
        Child.Result r = asNobody(shared, "out.png");
        assertEquals(2, r.status(), r.err());
        assertEquals("glint: --output: 'out.png' is read-only; make it writable (chmod u+w) or choose another output name\n",
                r.err());
        assertEquals("old", Files.readString(image));
        assertEquals("r--r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(image)));
    }

    /** In a folder this user may write, another user's image it may not write is left alone, as > would. */
    @Test
    void anotherUsersImageThisUserCannotWriteIsRefusedBeforeRendering() throws Exception {
        assumeTrue(isRoot(), "needs root to make a file of another user");
        Path shared = sharedFolder();
        Files.writeString(shared.resolve("scene.yaml"), SCENE);
        Files.writeString(shared.resolve("empty.properties"), "");
        Path image = Files.writeString(shared.resolve("out.png"), "root's"); // root's, mode 644, in nobody's folder
        Files.setPosixFilePermissions(image, PosixFilePermissions.fromString("rw-r--r--"));
        Child.Result r = asNobody(shared, "out.png");
        assertEquals(2, r.status(), r.err());
        assertEquals("glint: --output: 'out.png' belongs to another user and is not writable for this one; "
                + "choose another output name\n", r.err());
        assertEquals("root's", Files.readString(image));
    }

    @Test
    void anotherUsersImageInAStickyFolderIsRefusedBeforeRendering() throws Exception {
        assumeTrue(isRoot(), "needs root to make a file of another user");
        Path shared = sharedFolder();
        Path sticky = Files.createDirectory(shared.resolve("tmp"));
        Files.setPosixFilePermissions(sticky, PosixFilePermissions.fromString("rwxrwxrwx"));
        Files.setAttribute(sticky, "unix:mode", 01777);
        Files.writeString(shared.resolve("scene.yaml"), SCENE);
        Files.writeString(shared.resolve("empty.properties"), "");
        Path image = Files.writeString(sticky.resolve("out.png"), "root's");
        Files.setPosixFilePermissions(image, PosixFilePermissions.fromString("rw-rw-rw-")); // writable, not replaceable
        Child.Result r = asNobody(shared, "tmp/out.png");
        assertEquals(2, r.status(), r.err());
        assertEquals("glint: --output: 'tmp/out.png' belongs to another user, in a folder where only a file's owner may "
                + "replace it (sticky, like /tmp); choose another output name\n", r.err());
        assertEquals("root's", Files.readString(image));
        try (Stream<Path> list = Files.list(sticky)) {
            assertEquals(List.of("out.png"), list.map(p -> p.getFileName().toString()).toList(), "no temporary file left");
        }
    }

    private static boolean isRoot() throws Exception {
        Process id = new ProcessBuilder("id", "-u").start();
        String uid = new String(id.getInputStream().readAllBytes()).trim();
        return id.waitFor() == 0 && uid.equals("0") && Files.isExecutable(Path.of("/usr/bin/setpriv"));
    }

    /** A folder user nobody (65534) owns, with a copy of the program it can read. */
    private Path sharedFolder() throws Exception {
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        Path shared = Files.createDirectory(dir.resolve("shared"));
        Path program = Files.createDirectory(dir.resolve("program"));
        for (String part : Child.classPath().split(java.io.File.pathSeparator)) {
            Path from = Path.of(part);
            Path to = program.resolve(from.getFileName());
            try (Stream<Path> walk = Files.walk(from)) {
                for (Path p : walk.toList()) {
                    Files.copy(p, to.resolve(from.relativize(p).toString()));
                }
            }
        }
        try (Stream<Path> walk = Files.walk(program)) {
            for (Path p : walk.toList()) {
                Files.setPosixFilePermissions(p, PosixFilePermissions.fromString(Files.isDirectory(p) ? "rwxr-xr-x" : "rw-r--r--"));
            }
        }
        new ProcessBuilder("chown", "65534:65534", shared.toString()).start().waitFor();
        return shared;
    }

    /** Renders shared/scene.yaml to {@code output} as user nobody, in the shared folder. */
    private Child.Result asNobody(Path shared, String output) throws Exception {
        List<String> command = new ArrayList<>(List.of("setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"));
        List<String> javaCommand = Child.java();
        javaCommand.set(javaCommand.indexOf("-cp") + 1, String.join(java.io.File.pathSeparator,
                Stream.of(Child.classPath().split(java.io.File.pathSeparator))
                        .map(p -> dir.resolve("program").resolve(Path.of(p).getFileName()).toString()).toList()));
        command.addAll(javaCommand);
        command.addAll(List.of("--config", "empty.properties", "--scene", "scene.yaml", "--output", output,
                "--width", "8", "--height", "6", "--spp", "1"));
        return Child.sh(shared, "exec " + Child.line(command) + "\n", Map.of("HOME", shared.toString()));
    }
}
