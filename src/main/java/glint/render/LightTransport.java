package glint.render;

import java.util.List;

/**
 * How light is carried through a scene (docs/conventions.md, "Light that bounces"): {@link #WHITTED},
 * direct light and the mirror and glass rays it spawns, or {@link #PATH}, the rendering equation
 * solved by path tracing.
 */
public enum LightTransport {
    WHITTED("whitted"), PATH("path");

    /** The keys a config, a scene's {@code render:} block and {@code --integrator} accept. */
    public static final List<String> KEYS = List.of("whitted", "path");

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

    public LightTransport other() {
        return this == PATH ? WHITTED : PATH;
    }
}
