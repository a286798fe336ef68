package glint.study;

import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.render.LightTransport;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;

/**
 * Every sample of every pixel of a path-traced render, one at a time: pass p of a pixel's n samples
 * (n a perfect square) is its sample p alone, so the n passes are the n values a still of n samples
 * averages. Channel 0 only: the study scenes are grey.
 */
final class PassSamples {

    final int width, height, samples;
    /** Per pixel (row by row), its samples in pass order. */
    final float[][] values;

    private PassSamples(int width, int height, int samples) {
        this.width = width;
        this.height = height;
        this.samples = samples;
        values = new float[width * height][samples];
    }

    /** The path integrator's samples of a cook-torrance scene, {@code hits} surface hits along a path at most. */
    static PassSamples render(Scene scene, int width, int height, int samples, int hits, Tracer tracer) {
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, hits, 0, 1e-9)
                .withTransport(LightTransport.PATH);
        RenderScene compiled = RenderScene.compile(scene, settings);
        PassSamples out = new PassSamples(width, height, samples);
        FrameBuffer frame = new FrameBuffer(width, height);
        for (int pass = 0; pass < samples; pass++) {
            tracer.renderPass(compiled, frame, samples, pass, 4);
            float[] rgb = frame.rgb();
            for (int p = 0; p < width * height; p++) {
                out.values[p][pass] = rgb[3 * p];
            }
        }
        return out;
    }

    static Scene parse(String name, String yaml) {
        try {
            return SceneLoader.parse(name, yaml);
        } catch (InputException e) {
            throw new IllegalStateException("a study scene does not load: " + e.getMessage(), e);
        }
    }

    /** The mean of all samples of all pixels. */
    double mean() {
        double sum = 0;
        for (float[] pixel : values) {
            for (float v : pixel) {
                sum += v;
            }
        }
        return sum / ((double) values.length * samples);
    }

    /** The standard deviation of one sample about the mean of all (pixel differences included). */
    double sampleStd() {
        double mean = mean(), sum = 0;
        for (float[] pixel : values) {
            for (float v : pixel) {
                sum += (v - mean) * (v - mean);
            }
        }
        return Math.sqrt(sum / ((double) values.length * samples - 1));
    }

    /** The standard error of {@link #mean}: samples taken as independent, which stratification only makes conservative. */
    double standardError() {
        return sampleStd() / Math.sqrt((double) values.length * samples);
    }

    /** The largest sample; NaN if a sample is not finite. */
    double max() {
        double max = Double.NEGATIVE_INFINITY;
        for (float[] pixel : values) {
            for (float v : pixel) {
                if (!Float.isFinite(v)) {
                    return Double.NaN;
                }
                max = Math.max(max, v);
            }
        }
        return max;
    }
}
