package glint.scene;

import glint.math.Vector3d;
import glint.shading.Bsdf;
import glint.shading.Conductor;
import glint.shading.Dielectric;
import glint.shading.Lambert;

/**
 * A kind of material, registered once in {@link Registry}: its name in scene files (also the name of
 * its preset material), the preset's values (docs/scene-format.md and the phong table of
 * docs/conventions.md), and its {@link Bsdf}, how the physically based model scatters light at it. The
 * phong model reads only a material's coefficients, and passes kt of a light through a material whose
 * BSDF transmits.
 */
public final class MaterialType {

    public static final MaterialType MATTE = new MaterialType("matte", new Lambert(),
            new Vector3d(0.8, 0.8, 0.8), 0.99, 0.01, 0.0, 10);
    public static final MaterialType METAL = new MaterialType("metal", new Conductor(),
            new Vector3d(0.9, 0.9, 0.9), 0.1, 0.7, 0.0, 50);
    public static final MaterialType GLASS = new MaterialType("glass", new Dielectric(), Vector3d.ONE,
            0.01, 0.2, 0.79, 125);

    private final String name;
    private final Bsdf bsdf;
    private final Material preset;

    /** A type whose preset has the given colour and phong coefficients, ior 1.5 and roughness 0. */
    public MaterialType(String name, Bsdf bsdf, Vector3d color, double kd, double ks, double kt, double shininess) {
        this.name = name;
        this.bsdf = bsdf;
        this.preset = new Material(this, color, kd, ks, kt, shininess, 1.5, 0);
    }

    /** The name used in scene files. */
    public String name() {
        return name;
    }

    public Bsdf bsdf() {
        return bsdf;
    }

    /** The material its name alone means; a material of this type written in a scene starts from it. */
    public Material preset() {
        return preset;
    }

    @Override
    public String toString() {
        return name;
    }
}
