package glint.scene;

import java.util.Map;

/**
 * A scene's {@code render:} block: how the scene is meant to be seen. Every key is optional; a key not
 * written is null and leaves the config's value. A command-line flag beats it, and it beats
 * config.properties (docs/scene-format.md).
 *
 * @param shading      {@code cook-torrance} or {@code phong}, or null
 * @param integrator   {@code whitted} or {@code path}, or null
 * @param samples      samples per pixel (a perfect square), or null
 * @param recursionMax surface hits along a path, or null
 * @param minWeight    the pruning weight, or null
 * @param width        the still image's width in pixels, or null
 * @param height       the still image's height in pixels, or null
 * @param exposure     the view transform's exposure in stops, or null
 * @param tone         the view transform's tone curve ({@code standard} or {@code agx}), or null
 * @param noise        adaptive sampling's threshold (the config's {@code noise}), or null
 * @param maxSamples   adaptive sampling's cap (the config's {@code max_samples}), or null
 * @param file         the scene file, for messages
 * @param places       where each written key stands in the file, by its name
 */
public record RenderBlock(String shading, String integrator, Integer samples, Integer recursionMax, Double minWeight,
                          Integer width, Integer height, Double exposure, String tone, Double noise,
                          Integer maxSamples, String file, Map<String, Place> places) {

    /** A key's line and column in the scene file (from 1). */
    public record Place(int line, int column) {
    }

    /** No block: everything from the config. */
    public static final RenderBlock NONE = new RenderBlock(null, null, null, null, null, null, null, "", Map.of());

    public RenderBlock {
        places = Map.copyOf(places);
    }

    /** A block that leaves adaptive sampling as it is. */
    public RenderBlock(String shading, String integrator, Integer samples, Integer recursionMax, Double minWeight,
                       Integer width, Integer height, Double exposure, String tone, String file,
                       Map<String, Place> places) {
        this(shading, integrator, samples, recursionMax, minWeight, width, height, exposure, tone, null, null, file,
                places);
    }

    /** A block that leaves the view transform as it is. */
    public RenderBlock(String shading, String integrator, Integer samples, Integer recursionMax, Double minWeight,
                       Integer width, Integer height, String file, Map<String, Place> places) {
        this(shading, integrator, samples, recursionMax, minWeight, width, height, null, null, file, places);
    }

    /** Whether the block sets nothing. */
    public boolean isEmpty() {
        return shading == null && integrator == null && samples == null && recursionMax == null && minWeight == null && width == null
                && height == null && exposure == null && tone == null && noise == null && maxSamples == null;
    }

    /** Where a key stands, or (0, 0) when it is not written. */
    public Place place(String key) {
        return places.getOrDefault(key, new Place(0, 0));
    }
}
