package glint.render;

import java.util.List;

/**
 * How light is carried through a scene (docs/conventions.md, "Light that bounces"): {@link #WHITTED},
 * direct light and the mirror and glass rays it spawns; {@link #PATH}, the rendering equation solved
 * by path tracing from the camera; or {@link #BDPT}, the same equation solved by paths from both the
 * camera and the lights, joined (bidirectional path tracing).
 */
public enum LightTransport {
    WHITTED("whitted"), PATH("path"), BDPT("bdpt");

    /** The keys a config, a scene's {@code render:} block and {@code --integrator} accept. */
    public static final List<String> KEYS = List.of("whitted", "path", "bdpt");
    /** The keys in words, for an error message: "whitted, path or bdpt". */
    public static final String IN_WORDS = "whitted, path or bdpt";

    private final String key;

    LightTransport(String key) {
        this.key = key;
    }

    public String key() {
        return key;
    }

    /** The integrator named {@code key}, or null. */
    public static LightTransport byKey(String key) {
        for (LightTransport t : values()) {
            if (t.key.equals(key)) {
                return t;
            }
        }
        return null;
    }

    /**
     * Whether it solves the rendering equation (path and bdpt): it needs cook-torrance's BSDFs, a sky
     * lights the scene, and an image at rest refines without end.
     */
    public boolean physical() {
        return this != WHITTED;
    }

    /** The next integrator in the order whitted, path, bdpt, and from bdpt back to whitted (the window's key I). */
    public LightTransport next() {
        return values()[(ordinal() + 1) % values().length];
    }
}
