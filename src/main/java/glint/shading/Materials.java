package glint.shading;

import glint.math.Vector3d;
import java.util.List;

/**
 * A scene's materials in flat arrays, indexed by material number: what every material has (its BSDF,
 * Whitted's response, the colour and the phong model's coefficients), and each material's own numbers,
 * the ones its type compiled for its BSDF to read, one run in one flat array ({@link #parameter}).
 */
public final class Materials {

    private final Bsdf[] bsdf;
    private final WhittedResponse[] response;
    private final double[] color; // 3 per material, linear RGB
    private final double[] kd, ks, kt, shininess, ior;
    /** Where material m's own numbers start in {@link #data}. */
    private final int[] start;
    private final double[] data;
    private final boolean exactFresnel;
    /** Per material: whether Whitted's ambient light reaches it, and whether it sends light of its own. */
    private final boolean[] ambientLit, emits;
    /** Per material: the kinds of its lobes ({@link Bsdf#lobes}), asked once, and whether all are delta. */
    private final int[] lobes;
    private final boolean[] delta;

    private Materials(List<Material> materials, boolean exactFresnel) {
        this.exactFresnel = exactFresnel;
        int n = materials.size();
        bsdf = new Bsdf[n];
        response = new WhittedResponse[n];
        color = new double[3 * n];
        kd = new double[n];
        ks = new double[n];
        kt = new double[n];
        shininess = new double[n];
        ior = new double[n];
        start = new int[n];
        ambientLit = new boolean[n];
        emits = new boolean[n];
        lobes = new int[n];
        delta = new boolean[n];
        int size = 0;
        for (Material m : materials) {
            size += m.parameters.length;
        }
        data = new double[size];
        for (int i = 0, at = 0; i < n; i++) {
            Material m = materials.get(i);
            bsdf[i] = m.bsdf;
            response[i] = m.response;
            ambientLit[i] = m.response.ambientLit();
            emits[i] = m.bsdf.emits();
            color[3 * i] = m.color.x();
            color[3 * i + 1] = m.color.y();
            color[3 * i + 2] = m.color.z();
            kd[i] = m.kd;
            ks[i] = m.ks;
            kt[i] = m.kt;
            shininess[i] = m.shininess;
            ior[i] = m.ior;
            start[i] = at;
            System.arraycopy(m.parameters, 0, data, at, m.parameters.length);
            at += m.parameters.length;
        }
        for (int i = 0; i < n; i++) {
            lobes[i] = bsdf[i].lobes(this, i);
            delta[i] = Lobe.allDelta(lobes[i]);
        }
    }

    /**
     * A material as the compiled scene keeps it: its type's BSDF and Whitted's response, the colour and
     * the phong model's coefficients (kd, ks, kt, shininess and the ior it refracts at), and the numbers
     * its BSDF reads ({@link #parameter}), in the order the BSDF reads them.
     */
    public record Material(Bsdf bsdf, WhittedResponse response, Vector3d color, double kd, double ks, double kt,
                           double shininess, double ior, double[] parameters) {

        public Material {
            parameters = parameters.clone();
        }
    }

    /** The materials numbered in the order given. */
    public static Materials of(List<Material> materials) {
        return of(materials, true);
    }

    /** The materials numbered in the order given; glass reflects by the exact Fresnel equations or by Schlick's. */
    public static Materials of(List<Material> materials, boolean exactFresnel) {
        return new Materials(List.copyOf(materials), exactFresnel);
    }

    /** Whether a glass boundary reflects by the exact Fresnel equations (else by Schlick's). */
    public boolean exactFresnel() {
        return exactFresnel;
    }

    public int count() {
        return bsdf.length;
    }

    /** How material m scatters light in the physically based model. */
    public Bsdf bsdf(int m) {
        return bsdf[m];
    }

    /** Whether all of material m's lobes are delta (or it has none): no light sample sees them. */
    public boolean isDelta(int m) {
        return delta[m];
    }

    /**
     * The kinds of material m's lobes ({@link Bsdf#lobes}, {@link Lobe}'s bits): {@code
     * Lobe.transmitsNonDelta(lobes(m))} asks whether light samples reach it through the surface.
     */
    public int lobes(int m) {
        return lobes[m];
    }

    /** What Whitted's shading models ask of material m besides its BSDF: its single rays, ambient, shadows. */
    public WhittedResponse response(int m) {
        return response[m];
    }

    /** Whether Whitted's ambient light reaches material m, times its colour ({@link WhittedResponse#ambientLit}). */
    public boolean ambientLit(int m) {
        return ambientLit[m];
    }

    /** Whether material m sends light of its own ({@link Bsdf#emits}). */
    public boolean emits(int m) {
        return emits[m];
    }

    /** Albedo (matte), reflectance at normal incidence (metal) or transmission tint (glass): channel 0, 1, 2. */
    public double color(int m, int channel) {
        return color[3 * m + channel];
    }

    public double kd(int m) {
        return kd[m];
    }

    public double ks(int m) {
        return ks[m];
    }

    public double kt(int m) {
        return kt[m];
    }

    public double shininess(int m) {
        return shininess[m];
    }

    /** The index the phong model refracts material m's kt at (a glass's BSDF reads its own). */
    public double ior(int m) {
        return ior[m];
    }

    /**
     * Number k of material m's own numbers, the ones its type compiled for its BSDF
     * ({@code glint.registry.MaterialType}): the BSDF knows what each k means.
     */
    public double parameter(int m, int k) {
        return data[start[m] + k];
    }
}
