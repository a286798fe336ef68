package glint.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import glint.render.Shading;
import org.junit.jupiter.api.Test;

/** Each {@code with...} copy changes its own fields and keeps every other one. */
class ConfigTest {

    private static final Limits LIMITS = new Limits(1000, 2000, 30, 4, 50);

    /** A config whose every field differs from the defaults, so a field copied wrongly shows. */
    private static final Config BASE = new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/a.yaml", 3,
            Shading.PHONG, 9, 0.05, 1.5, 45, 24, LIMITS, true);

    @Test
    void eachCopyChangesItsFieldsAndKeepsTheOthers() {
        assertEquals(new Config(true, 1e-7, 3, 5, 320, 200, 7, "Test", "scenes/a.yaml", 3, Shading.PHONG, 9, 0.05,
                1.5, 45, 24, LIMITS, true), BASE.withSize(320, 200));
        assertEquals(new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/a.yaml", 3, Shading.PHONG, 16, 0.05,
                1.5, 45, 24, LIMITS, true), BASE.withSamples(16));
        assertEquals(new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/a.yaml", 8, Shading.PHONG, 9, 0.05,
                1.5, 45, 24, LIMITS, true), BASE.withThreads(8));
        assertEquals(new Config(true, 1e-7, 3, 5, 640, 480, 12, "Test", "scenes/a.yaml", 3, Shading.PHONG, 9, 0.05,
                1.5, 45, 24, LIMITS, true), BASE.withRecursionMax(12));
        assertEquals(new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/a.yaml", 3, Shading.COOK_TORRANCE, 9,
                0.05, 1.5, 45, 24, LIMITS, true), BASE.withShading(Shading.COOK_TORRANCE));
        assertEquals(new Config(true, 1e-7, 3, 11, 640, 480, 7, "Test", "scenes/a.yaml", 3, Shading.PHONG, 9, 0.05,
                1.5, 45, 24, LIMITS, true), BASE.withScreenDivider(11));
        assertEquals(new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/a.yaml", 3, Shading.PHONG, 9, 0.0,
                1.5, 45, 24, LIMITS, true), BASE.withMinWeight(0.0));
        assertEquals(new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/b.yaml", 3, Shading.PHONG, 9, 0.05,
                1.5, 45, 24, LIMITS, true), BASE.withScene("scenes/b.yaml"));
        assertEquals(new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/a.yaml", 3, Shading.PHONG, 9, 0.05,
                1.5, 45, 24, Limits.DEFAULT, true), BASE.withLimits(Limits.DEFAULT));
        assertEquals(new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/a.yaml", 3, Shading.PHONG, 9, 0.05,
                1.5, 45, 24, LIMITS, false), BASE.withFreeFlight(false));
    }

    @Test
    void aCopyIsANewConfigAndTheOriginalStays() {
        Config copy = BASE.withSamples(1).withThreads(1);
        assertNotEquals(BASE, copy);
        assertEquals(9, BASE.samples());
        assertEquals(3, BASE.threads());
        assertEquals(BASE, copy.withSamples(9).withThreads(3));
    }

    @Test
    void theShortConstructorKeepsTheHorizonLevel() {
        Config level = new Config(true, 1e-7, 3, 5, 640, 480, 7, "Test", "scenes/a.yaml", 3, Shading.PHONG, 9,
                0.05, 1.5, 45, 24, LIMITS);
        assertEquals(BASE.withFreeFlight(false), level);
    }
}
