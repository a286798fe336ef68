package glint.scenefile;

/**
 * How big a scene the loader accepts, so that a mistaken or hostile file is refused up front
 * instead of exhausting memory or time. Set from config.properties (docs/config.md).
 *
 * @param maxFileBytes largest scene file, in bytes ({@code max_scene_bytes})
 * @param maxObjects   most objects ({@code max_objects})
 * @param maxLights    most lights ({@code max_lights})
 */
public record SceneLimits(long maxFileBytes, int maxObjects, int maxLights) {

    public static final SceneLimits DEFAULT = new SceneLimits(8L << 20, 100_000, 1_000);

    /** Deepest nesting of lists and mappings a scene file may have; a scene needs 4. */
    public static final int MAX_NESTING = 32;

    /**
     * Longest line a scene file may have, in characters: the YAML reader's time grows with the square
     * of a line's length (a 1 MB line takes seconds).
     */
    public static final int MAX_LINE_CHARS = 65_536;
}
