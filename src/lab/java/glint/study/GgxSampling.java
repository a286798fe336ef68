package glint.study;

import glint.math.Vector3d;
import glint.shading.BsdfSample;
import glint.shading.Conductor;
import glint.shading.Materials;
import glint.shading.MetalResponse;
import glint.shading.Optics;
import glint.shading.Surface;
import java.util.List;

/**
 * Sampling a white GGX conductor (F = 1) for a view at cosine mu to the normal: Glint's, the normals
 * visible from the view (Heitz 2018) with weight G2 / G1, through {@link Conductor#sample}; and the
 * textbook's, the distribution of normals D(h) h.n (Walter et al. 2007) with weight
 * G2 (wo.h) / (wo.n h.n), modelled here. The numbers are a grid of n x n stratified midpoints, so
 * every result is a pure function of its arguments. Local frame: normal +z, wo in the xz plane.
 */
final class GgxSampling {

    /** What one method's n x n samples gave: the largest weight, the mean, the share lost, the spread. */
    record Stats(double maxWeight, double meanWeight, double lostFraction, double relativeStd, int nonFinite) {
    }

    private GgxSampling() {
    }

    /** Glint's sampling through the renderer's conductor. */
    static Stats glint(double roughness, double mu, int n) {
        Conductor conductor = new Conductor();
        Materials m = Materials.of(List.of(new Materials.Material(conductor, new MetalResponse(),
                new Vector3d(1, 1, 1), 0, 0, 0, 0, 1.5, Conductor.parameters(roughness))));
        Surface s = new Surface();
        s.nz = 1;
        s.cosIncident = mu;
        s.front = true;
        BsdfSample out = new BsdfSample();
        double sin = Math.sqrt(Math.max(0, 1 - mu * mu));
        Accumulator a = new Accumulator();
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                boolean sampled = conductor.sample(m, s, sin, 0, mu, (i + 0.5) / n, (j + 0.5) / n, 0.5, out);
                a.add(sampled ? out.weightR : 0, sampled);
            }
        }
        return a.stats();
    }

    /** The textbook's: h from D(h) h.n, wi = wo mirrored about h, weight G2 (wo.h) / (wo.n h.n) where wi is above. */
    static Stats textbook(double roughness, double mu, int n) {
        double alpha = roughness * roughness;
        double sin = Math.sqrt(Math.max(0, 1 - mu * mu));
        Accumulator a = new Accumulator();
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double u1 = (i + 0.5) / n, phi = 2 * Math.PI * (j + 0.5) / n;
                double tan2 = alpha * alpha * u1 / (1 - u1);
                double cosH = 1 / Math.sqrt(1 + tan2), sinH = Math.sqrt(Math.max(0, 1 - cosH * cosH));
                double hx = sinH * Math.cos(phi), hy = sinH * Math.sin(phi);
                double cosOutHalf = sin * hx + mu * cosH;
                double cosIn = 2 * cosOutHalf * cosH - mu;
                if (!(cosOutHalf > 0) || !(cosIn > 0)) {
                    a.add(0, false);
                    continue;
                }
                double g2 = 4 * Optics.smithVisibility(cosIn, mu, alpha) * cosIn * mu;
                a.add(g2 * cosOutHalf / (mu * cosH), true);
            }
        }
        return a.stats();
    }

    /** Running sums of one method's weights (a lost sample counts as weight 0). */
    private static final class Accumulator {
        private double sum, sumSquares, max;
        private int count, lost, nonFinite;

        void add(double weight, boolean sampled) {
            count++;
            if (!sampled) {
                lost++;
                return;
            }
            if (!Double.isFinite(weight)) {
                nonFinite++;
                return;
            }
            sum += weight;
            sumSquares += weight * weight;
            max = Math.max(max, weight);
        }

        Stats stats() {
            double mean = sum / count;
            double variance = Math.max(0, sumSquares / count - mean * mean);
            return new Stats(max, mean, (double) lost / count, mean > 0 ? Math.sqrt(variance) / mean : 0, nonFinite);
        }
    }
}
