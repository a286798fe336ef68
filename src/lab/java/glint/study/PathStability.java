package glint.study;

import glint.render.Tracer;
import glint.shading.Microfacet;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The path integrator's part of the stability study (stability.md, section 6): GGX sampling at
 * grazing views and tiny roughness, fireflies from a glossy bounce to a point light, a bright sky
 * through glass. Each writes a chart into {@code images} and returns its table.
 */
final class PathStability {

    /** Views as cosines to the normal, from straight on to 1e-6 (89.99994 degrees). */
    static final double[] VIEW_COSINES = cosines(1e-6, 25);
    /** Roughness just above the delta mirror's threshold (alpha = MIRROR_ALPHA) up to 1. */
    static final double[] GGX_ROUGHNESS = {Math.sqrt(Microfacet.MIRROR_ALPHA) * 1.001, 0.1, 0.3, 1};
    static final int GGX_GRID = 128;
    /** Roughness of the firefly wall, from below the delta mirror's threshold to 1. */
    static final double[] FIREFLY_ROUGHNESS = {0.0316, 0.0317, 0.04, 0.06, 0.1, 0.15, 0.2, 0.3, 0.5, 0.7, 1};
    static final int[] FIREFLY_SAMPLES = {64, 1024};
    static final int[] GLASS_HITS = {3, 5, 16};
    static final int GLASS_SAMPLES = 256;

    private PathStability() {
    }

    /** cos = 1 and then n - 1 values spaced evenly in log down to {@code smallest}. */
    static double[] cosines(double smallest, int n) {
        double[] c = new double[n];
        for (int i = 0; i < n; i++) {
            c[i] = Math.pow(smallest, (double) i / (n - 1));
        }
        return c;
    }

    static String ggx(Path images) throws IOException {
        int n = VIEW_COSINES.length;
        GgxSampling.Stats[][] glint = new GgxSampling.Stats[GGX_ROUGHNESS.length][n];
        GgxSampling.Stats[][] textbook = new GgxSampling.Stats[GGX_ROUGHNESS.length][n];
        for (int r = 0; r < GGX_ROUGHNESS.length; r++) {
            for (int i = 0; i < n; i++) {
                glint[r][i] = GgxSampling.glint(GGX_ROUGHNESS[r], VIEW_COSINES[i], GGX_GRID);
                textbook[r][i] = GgxSampling.textbook(GGX_ROUGHNESS[r], VIEW_COSINES[i], GGX_GRID);
            }
        }
        PathStabilityCharts.ggx(VIEW_COSINES, GGX_ROUGHNESS, glint, textbook, images.resolve("stability-ggx-sampling.png"));
        StringBuilder md = new StringBuilder(String.format(Locale.ROOT, "White GGX conductor (F = 1), %d x %d stratified "
                + "samples a view; each cell: Glint (visible normals) / textbook (all normals). Largest weight, "
                + "and the relative standard deviation of one sample's weight in brackets:%n%n", GGX_GRID, GGX_GRID));
        md.append("| roughness |");
        int[] columns = {0, 4, 8, 12, 24};
        for (int c : columns) {
            md.append(" cos ").append(Numbers.sci(VIEW_COSINES[c]).replace("1e0", "1")).append(" |");
        }
        md.append(" non-finite, Glint |\n|--:").append("|--:".repeat(columns.length + 1)).append("|\n");
        for (int r = 0; r < GGX_ROUGHNESS.length; r++) {
            md.append("| ").append(Numbers.fixed(GGX_ROUGHNESS[r], 4));
            int nonFinite = 0;
            for (GgxSampling.Stats s : glint[r]) {
                nonFinite += s.nonFinite();
            }
            for (int c : columns) {
                GgxSampling.Stats g = glint[r][c], t = textbook[r][c];
                md.append(String.format(Locale.ROOT, " | %.3f (%.2f) / %.1f (%.2f)", g.maxWeight(), g.relativeStd(),
                        t.maxWeight(), t.relativeStd()));
            }
            md.append(" | ").append(nonFinite).append(" |\n");
        }
        return md.toString();
    }

    static String fireflies(Path images, Tracer tracer) throws IOException {
        double mirror = Fireflies.imageMean(true, 4), direct = Fireflies.imageMean(false, 4);
        int n = FIREFLY_ROUGHNESS.length;
        double[][] mean = new double[FIREFLY_SAMPLES.length][n], error = new double[FIREFLY_SAMPLES.length][n];
        double[] relativeStd = new double[n], maxOverMean = new double[n];
        for (int b = 0; b < FIREFLY_SAMPLES.length; b++) {
            for (int r = 0; r < n; r++) {
                PassSamples s = Fireflies.render(FIREFLY_ROUGHNESS[r], FIREFLY_SAMPLES[b], tracer);
                mean[b][r] = s.mean() / mirror;
                error[b][r] = s.standardError() / mirror;
                if (b == FIREFLY_SAMPLES.length - 1) {
                    relativeStd[r] = s.sampleStd() / s.mean();
                    maxOverMean[r] = s.max() / s.mean();
                }
            }
        }
        PathStabilityCharts.fireflies(FIREFLY_ROUGHNESS, FIREFLY_SAMPLES, mean, error, direct / mirror, relativeStd,
                maxOverMean, images.resolve("stability-fireflies.png"));
        int big = FIREFLY_SAMPLES.length - 1;
        StringBuilder md = new StringBuilder(String.format(Locale.ROOT, "Floor lit by a point light and by a white metal "
                + "wall, %d x %d pixels, paths of 2 hits; the mirror-image closed form is %.4f, the direct light alone "
                + "%.4f (the image's mean radiance). At %d and %d samples a pixel:%n%n", Fireflies.WIDTH,
                Fireflies.HEIGHT, mirror, direct, FIREFLY_SAMPLES[0], FIREFLY_SAMPLES[big]));
        md.append(String.format(Locale.ROOT, "| roughness | alpha | mean / mirror, %d spp | mean / mirror, %d spp "
                + "| std of a sample / mean | largest sample / mean |%n|--:|--:|--:|--:|--:|--:|%n", FIREFLY_SAMPLES[0],
                FIREFLY_SAMPLES[big]));
        for (int r = 0; r < n; r++) {
            double roughness = FIREFLY_ROUGHNESS[r];
            md.append(String.format(Locale.ROOT, "| %s | %s | %.3f ± %.3f | %.3f ± %.3f | %.1f | %.0f |%n",
                    Numbers.fixed(roughness, 4), Numbers.sci(roughness * roughness), mean[0][r], error[0][r],
                    mean[big][r], error[big][r], relativeStd[r], maxOverMean[r]));
        }
        return md.toString();
    }

    static String glass(Path images, Tracer tracer) throws IOException {
        double[] impacts = GlassSky.centreImpacts();
        double[][] measured = new double[GLASS_HITS.length][];
        StringBuilder md = new StringBuilder(String.format(Locale.ROOT, "Clear glass ball (ior %.1f) in a uniform sky of "
                + "radiance %.0f, no lights, %d x %d pixels, %d samples a pixel. Without a floor (a furnace: the exact "
                + "image is the sky everywhere):%n%n| hits | samples that are exactly the sky or 0 | samples 0 | expected "
                + "(closed form) | image mean / sky |%n|--:|--:|--:|--:|--:|%n", GlassSky.IOR, GlassSky.SKY,
                GlassSky.WIDTH, GlassSky.HEIGHT, GLASS_SAMPLES));
        for (int h = 0; h < GLASS_HITS.length; h++) {
            PassSamples s = GlassSky.render(false, GLASS_SAMPLES, GLASS_HITS[h], tracer);
            double[] expected = GlassSky.furnaceExpected(GLASS_HITS[h], 4);
            measured[h] = new double[impacts.length];
            long zeros = 0, exact = 0;
            double expectedZeros = 0;
            for (int p = 0; p < impacts.length; p++) {
                double sum = 0;
                for (float v : s.values[p]) {
                    sum += v;
                    zeros += v == 0 ? 1 : 0;
                    exact += v == 0 || v == (float) GlassSky.SKY ? 1 : 0;
                }
                measured[h][p] = sum / GLASS_SAMPLES / GlassSky.SKY;
                expectedZeros += (1 - expected[p]) * GLASS_SAMPLES;
            }
            md.append(String.format(Locale.ROOT, "| %d | %d of %d | %d | %.1f | %.5f |%n", GLASS_HITS[h], exact,
                    (long) impacts.length * GLASS_SAMPLES, zeros, expectedZeros, s.mean() / GlassSky.SKY));
        }
        PassSamples floor = GlassSky.render(true, GLASS_SAMPLES, 16, tracer);
        double[] pixelStd = new double[impacts.length];
        for (int p = 0; p < impacts.length; p++) {
            double m = 0, q = 0;
            for (float v : floor.values[p]) {
                m += v;
                q += (double) v * v;
            }
            m /= GLASS_SAMPLES;
            pixelStd[p] = m > 0 ? Math.sqrt(Math.max(0, q / GLASS_SAMPLES - m * m)) / m : 0;
        }
        PathStabilityCharts.glass(impacts, GLASS_HITS, measured, pixelStd, GlassSky.WIDTH,
                images.resolve("stability-glass-sky.png"));
        md.append(String.format(Locale.ROOT, "%nOver a black floor (16 hits): image mean %.3f ± %.3f, largest sample "
                + "%.3f (the sky: %.0f).%n", floor.mean(), floor.standardError(), floor.max(), GlassSky.SKY));
        return md.toString();
    }
}
