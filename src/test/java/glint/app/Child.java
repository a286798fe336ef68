package glint.app;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** The real program in a JVM of its own, as a user starts it: for locales, signals and other users. */
final class Child {

    private Child() {
    }

    /** What a finished run printed and returned. */
    record Result(int status, String out, String err) {
    }

    /** The java command and the class path of the program (target/classes and its jars). */
    static List<String> java(String... jvmOptions) throws Exception {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(List.of(jvmOptions));
        command.add("-cp");
        command.add(classPath());
        command.add("glint.app.Main");
        return command;
    }

    static String classPath() throws Exception {
        List<String> parts = new ArrayList<>();
        for (Class<?> c : List.of(Main.class, picocli.CommandLine.class, org.snakeyaml.engine.v2.api.LoadSettings.class)) {
            parts.add(Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString());
        }
        return String.join(File.pathSeparator, parts);
    }

    /**
     * Runs a shell script (its bytes as written, so that file names and arguments reach the program
     * byte for byte, whatever this JVM's own locale) in {@code dir}, with the environment changed by
     * {@code env}, and waits for it.
     */
    static Result sh(Path dir, String script, Map<String, String> env) throws IOException, InterruptedException {
        Path file = dir.resolve("run.sh");
        Files.write(file, script.getBytes(StandardCharsets.UTF_8));
        ProcessBuilder builder = new ProcessBuilder("/bin/sh", file.toString()).directory(dir.toFile());
        builder.environment().putAll(env);
        Path out = dir.resolve("stdout.txt"), err = dir.resolve("stderr.txt");
        builder.redirectOutput(out.toFile()).redirectError(err.toFile());
        int status = builder.start().waitFor();
        Result result = new Result(status, Files.readString(out, StandardCharsets.ISO_8859_1),
                Files.readString(err, StandardCharsets.ISO_8859_1));
        Files.delete(file);
        Files.delete(out);
        Files.delete(err);
        return result;
    }

    /** A word of a shell script, quoted. */
    static String quote(String word) {
        return "'" + word.replace("'", "'\\''") + "'";
    }

    /** The words of a command as one line of a shell script. */
    static String line(List<String> words) {
        return String.join(" ", words.stream().map(Child::quote).toList());
    }
}
