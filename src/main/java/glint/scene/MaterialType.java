package glint.scene;

/** The closed set of material kinds; each is also a preset material name. */
public enum MaterialType {
    MATTE("matte"), METAL("metal"), GLASS("glass");

    private final String key;

    MaterialType(String key) {
        this.key = key;
    }

    /** The name used in scene files. */
    public String key() {
        return key;
    }
}
