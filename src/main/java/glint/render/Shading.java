package glint.render;

/** The shading models of docs/conventions.md ("Shading models"). */
public enum Shading {
    COOK_TORRANCE("cook-torrance"), PHONG("phong");

    private final String key;

    Shading(String key) {
        this.key = key;
    }

    public String key() {
        return key;
    }

    /** The model named {@code key}, or null. */
    public static Shading byKey(String key) {
        for (Shading s : values()) {
            if (s.key.equals(key)) {
                return s;
            }
        }
        return null;
    }

    public Shading other() {
        return this == PHONG ? COOK_TORRANCE : PHONG;
    }
}
