package glint.scenefile;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import glint.config.Limits;
import glint.input.InputException;
import glint.scene.Scene;
import java.nio.charset.StandardCharsets;
import java.util.regex.Pattern;

/**
 * Fuzzes the scene loader: whatever the text, it either yields a scene or an {@link InputException}
 * whose message has the user-facing form "file[:line[:col]]: problem" - never another exception,
 * never a hang. In `mvn verify` this replays the seed inputs in
 * src/test/resources/glint/scenefile/SceneLoaderFuzzTestInputs; with JAZZER_FUZZ=1 it fuzzes (docs/reliability.md).
 */
class SceneLoaderFuzzTest {

    private static final Pattern MESSAGE = Pattern.compile("fuzz\\.yaml(:\\d+(:\\d+)?)?: \\S.*", Pattern.DOTALL);
    /** Small limits keep each input fast; the limits themselves are tested elsewhere. */
    private static final SceneLimits LIMITS = new Limits(1 << 20, 64 * 1024, 2_000, 100, 16).scene();

    @FuzzTest(maxDuration = "5m")
    void anyTextLoadsOrIsRefusedWithAPositionedMessage(byte[] input) {
        loadsOrIsRefusedCleanly(new String(input, StandardCharsets.UTF_8));
    }

    /** The property every input must have; shared with the seeded mutation test. */
    static void loadsOrIsRefusedCleanly(String text) {
        try {
            Scene scene = SceneLoader.parse("fuzz.yaml", text, LIMITS);
            assertTrue(scene.objects().size() <= LIMITS.maxObjects());
            scene.objects().forEach(o -> assertTrue(o.material() != null));
        } catch (InputException e) {
            assertTrue(MESSAGE.matcher(e.getMessage()).matches(), e.getMessage());
        }
    }
}
