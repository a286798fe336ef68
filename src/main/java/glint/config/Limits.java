package glint.config;

import glint.scenefile.SceneLimits;

/**
 * Safety limits, so that a mistaken size or a hostile file is refused up front with a message
 * instead of exhausting memory or time. Each is a config key (docs/config.md).
 *
 * @param maxImagePixels largest image, width x height ({@code max_image_pixels})
 * @param maxSceneBytes  largest scene file ({@code max_scene_bytes})
 * @param maxObjects     most objects in a scene ({@code max_objects})
 * @param maxLights      most lights in a scene ({@code max_lights})
 * @param maxRecursion   largest recursion_max or --depth ({@code max_recursion})
 */
public record Limits(long maxImagePixels, long maxSceneBytes, int maxObjects, int maxLights, int maxRecursion) {

    /** 7680 x 4320 (8K UHD): a 400 MB float frame buffer; 8 MiB of scene; 100,000 objects. */
    public static final Limits DEFAULT = new Limits(7680L * 4320, SceneLimits.DEFAULT.maxFileBytes(),
            SceneLimits.DEFAULT.maxObjects(), SceneLimits.DEFAULT.maxLights(), 64);

    /**
     * The largest {@code max_image_pixels}: a frame of 3 floats a pixel must fit one Java array
     * (2^31 - 9 elements, 715,827,879 pixels).
     */
    public static final long MAX_IMAGE_PIXELS = 700_000_000L;

    /** The largest {@code max_recursion}: a path of 64 surface hits. */
    public static final int MAX_RECURSION = 64;

    public SceneLimits scene() {
        return new SceneLimits(maxSceneBytes, maxObjects, maxLights);
    }

    /** Null when width x height is allowed, otherwise why not. */
    public String imageSizeProblem(long width, long height) {
        if (width * height <= maxImagePixels) {
            return null;
        }
        String size = megapixels(width * height), largest = megapixels(maxImagePixels);
        if (size.equals(largest)) { // 7681x4320 beside 7680x4320: the difference shows only in pixels
            size = String.format(java.util.Locale.ROOT, "%,d pixels", width * height);
            largest = String.format(java.util.Locale.ROOT, "%,d pixels", maxImagePixels);
        }
        return String.format(java.util.Locale.ROOT,
                "%dx%d is %s; the largest image allowed is %s (config key max_image_pixels)", width, height, size, largest);
    }

    private static String megapixels(long pixels) {
        return String.format(java.util.Locale.ROOT, "%.1f megapixels", pixels / 1e6);
    }
}
