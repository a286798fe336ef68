package glint.scenefile;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * A short, reproducible fuzz run for every build: fixed-seed random mutations (byte flips,
 * insertions of YAML punctuation, deletions, duplicated and spliced lines) of the seed and malformed
 * corpora, each checked with the fuzz test's property. The open-ended coverage-guided run is
 * {@link SceneLoaderFuzzTest} with JAZZER_FUZZ=1.
 */
class SceneLoaderMutationTest {

    private static final long SEED = 0x61C0FFEEL;
    private static final int MUTANTS_PER_INPUT = 150;
    private static final String[] TOKENS = {"[", "]", "{", "}", ":", "- ", ",", "&a ", "*a", "!!str ", "\n  ",
        "'", "\"", "#", "1e999", ".nan", "-", "~", "null", "type: ", "sphere", "radius: ", "\t", "? "};

    @Test
    void mutatedScenesLoadOrAreRefusedCleanly() throws IOException {
        List<String> corpus = corpus();
        SplittableRandom random = new SplittableRandom(SEED);
        for (String original : corpus) {
            for (int i = 0; i < MUTANTS_PER_INPUT; i++) {
                SceneLoaderFuzzTest.loadsOrIsRefusedCleanly(mutate(original, corpus, random));
            }
        }
    }

    static String mutate(String text, List<String> corpus, SplittableRandom random) {
        StringBuilder s = new StringBuilder(text);
        int edits = 1 + random.nextInt(4);
        for (int e = 0; e < edits; e++) {
            int at = s.length() == 0 ? 0 : random.nextInt(s.length());
            switch (random.nextInt(5)) {
                case 0 -> s.insert(at, TOKENS[random.nextInt(TOKENS.length)]);
                case 1 -> {
                    if (s.length() > 0) {
                        s.delete(at, Math.min(s.length(), at + 1 + random.nextInt(12)));
                    }
                }
                case 2 -> {
                    if (s.length() > 0) {
                        s.setCharAt(at, (char) random.nextInt(32, 127));
                    }
                }
                case 3 -> {
                    String other = corpus.get(random.nextInt(corpus.size()));
                    int from = other.isEmpty() ? 0 : random.nextInt(other.length());
                    s.insert(at, other, from, Math.min(other.length(), from + random.nextInt(80)));
                }
                default -> {
                    int lineStart = s.lastIndexOf("\n", at) + 1;
                    int lineEnd = s.indexOf("\n", at);
                    if (lineEnd > lineStart) {
                        s.insert(lineStart, s.substring(lineStart, lineEnd + 1));
                    }
                }
            }
        }
        return s.toString();
    }

    private static List<String> corpus() throws IOException {
        List<String> texts = new ArrayList<>();
        for (Path folder : List.of(Path.of("src/test/resources/glint/scenefile/SceneLoaderFuzzTestInputs"),
                Path.of("src/test/resources/malformed"), Path.of("scenes"))) {
            try (Stream<Path> files = Files.walk(folder)) {
                for (Path file : files.filter(Files::isRegularFile).sorted().toList()) {
                    if (Files.size(file) < 20_000 && !file.toString().endsWith(".tsv")) {
                        texts.add(new String(Files.readAllBytes(file), StandardCharsets.UTF_8));
                    }
                }
            }
        }
        return texts;
    }
}
