package glint.study;

import glint.render.Tracer;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Lights with a size in the stability study (stability.md, section 7): the width of a small light's
 * cone, and fireflies from a glossy bounce to a small sphere light under three ways of finding it.
 * Each writes a chart into {@code images} and returns its table.
 */
final class LightStability {

    /** Sphere light radii of the firefly study (the light is 0.3 from the wall, 0.5 above the floor). */
    static final double[] RADII = {0.005, 0.02, 0.05, 0.1};
    /** Roughness of the wall. */
    static final double[] ROUGHNESS = {0.04, 0.06, 0.1, 0.2};
    static final int SAMPLES = 1 << 18;
    static final int REFERENCE_SAMPLES = 1 << 21;
    /** The product's samples a pixel, {@link SizedLightFireflies#PIXELS}^2 pixels. */
    static final int PRODUCT_SAMPLES = 1024;
    static final long SEED = 7, REFERENCE_SEED = 1;

    private LightStability() {
    }

    static String cone(Path images) throws IOException {
        double[] ratios = ConeWidth.ratios();
        ConeWidth.Row[] rows = new ConeWidth.Row[ratios.length];
        double largest = 0;
        for (int i = 0; i < ratios.length; i++) {
            rows[i] = ConeWidth.at(ratios[i]);
            largest = Math.max(largest, rows[i].glintError());
        }
        LightStabilityCharts.cone(rows, images.resolve("stability-cone.png"));
        StringBuilder md = new StringBuilder(String.format(Locale.ROOT, "A sphere light of radius r seen from distance "
                + "d: relative error of the cone's width 1 - cos theta_max (for Glint: of the irradiance its sample "
                + "stands for, which is the width times 2 pi L), and that irradiance over c I / d^2. Glint's largest "
                + "error over the %d ratios from 10^-0.25 to 10^-12: %.2f u.%n%n", ratios.length, largest / ConeWidth.U));
        md.append("| r / d | textbook 1 - sqrt(1 - r^2/d^2): relative error | Glint: relative error | irradiance / (c I / d^2): "
                + "exact | textbook | Glint |\n|--:|--:|--:|--:|--:|--:|\n");
        for (ConeWidth.Row r : rows) {
            double log = Math.log10(r.ratio());
            if (Math.abs(log - Math.rint(log)) > 1e-9) {
                continue;
            }
            md.append(String.format(Locale.ROOT, "| 1e%d | %.1e | %.1f u | %.15f | %.6f | %.15f |%n", (int) Math.rint(log),
                    r.textbookError(), r.glintError() / ConeWidth.U, r.exactIrradiance(), r.textbookIrradiance(),
                    r.glintIrradiance()));
        }
        return md.toString();
    }

    /** Per radius, roughness and method (the product, then each strategy): the figures of the study. */
    record Cell(SizedLightFireflies.Stats reference, SizedLightFireflies.Stats[] methods) {
    }

    static Cell cell(double radius, double roughness, int samples, int referenceSamples, int productSamples,
                     Tracer tracer) {
        SizedLightFireflies study = new SizedLightFireflies(roughness, radius);
        SizedLightFireflies.Strategy[] strategies = SizedLightFireflies.Strategy.values();
        SizedLightFireflies.Stats[] methods = new SizedLightFireflies.Stats[strategies.length + 1];
        methods[0] = SizedLightFireflies.Stats.of(SizedLightFireflies.render(roughness, radius, productSamples, tracer));
        for (int s = 0; s < strategies.length; s++) {
            methods[s + 1] = SizedLightFireflies.Stats.of(study.samples(strategies[s], samples, SEED));
        }
        SizedLightFireflies.Stats reference = SizedLightFireflies.Stats.of(
                study.samples(SizedLightFireflies.Strategy.MIS, referenceSamples, REFERENCE_SEED));
        return new Cell(reference, methods);
    }

    static String[] methodLabels() {
        SizedLightFireflies.Strategy[] strategies = SizedLightFireflies.Strategy.values();
        String[] labels = new String[strategies.length + 1];
        labels[0] = "Glint's path integrator";
        for (int s = 0; s < strategies.length; s++) {
            labels[s + 1] = strategies[s].label;
        }
        return labels;
    }

    static String fireflies(Path images, Tracer tracer) throws IOException {
        Cell[][] cells = new Cell[RADII.length][ROUGHNESS.length];
        for (int r = 0; r < RADII.length; r++) {
            for (int g = 0; g < ROUGHNESS.length; g++) {
                cells[r][g] = cell(RADII[r], ROUGHNESS[g], SAMPLES, REFERENCE_SAMPLES, PRODUCT_SAMPLES, tracer);
            }
        }
        String[] labels = methodLabels();
        LightStabilityCharts.fireflies(RADII, ROUGHNESS, labels, cells, images.resolve("stability-sized-fireflies.png"));
        int product = SizedLightFireflies.PIXELS * SizedLightFireflies.PIXELS * PRODUCT_SAMPLES;
        StringBuilder md = new StringBuilder(String.format(Locale.ROOT, "The floor point (0.8, 0, 0.1) of section 6b's "
                + "scene, its point light made a sphere light of radius r and the same power, paths of 2 hits. Reference: "
                + "light and BSDF samples by the power heuristic, %,d samples (its mean and standard error); Glint's path "
                + "integrator %,d samples, each strategy %,d. Each cell: mean / reference ± standard error, std of a "
                + "sample / mean, largest sample / mean.%n%n", REFERENCE_SAMPLES, product, SAMPLES));
        md.append("| r | roughness | reference | ").append(String.join(" | ", labels)).append(" |\n|--:|--:|--:")
                .append("|--:".repeat(labels.length)).append("|\n");
        for (int r = 0; r < RADII.length; r++) {
            for (int g = 0; g < ROUGHNESS.length; g++) {
                Cell c = cells[r][g];
                double ref = c.reference().mean();
                md.append(String.format(Locale.ROOT, "| %s | %s | %.3f ± %.3f", Numbers.fixed(RADII[r], 3),
                        Numbers.fixed(ROUGHNESS[g], 2), ref, c.reference().standardError()));
                for (SizedLightFireflies.Stats s : c.methods()) {
                    md.append(String.format(Locale.ROOT, " | %.2f ± %.2f, %.1f, %.0f", s.mean() / ref,
                            s.standardError() / ref, s.relativeStd(), s.maxOverMean()));
                }
                md.append(" |\n");
            }
        }
        return md.toString();
    }
}
