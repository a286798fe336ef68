package glint.study;

import glint.image.FrameBuffer;

/**
 * Relative mean squared error as the reference images' README defines it: the mean over all pixels
 * and the three channels of (a - r)^2 / (r^2 + 0.01), a the rendered and r the reference linear value.
 */
public final class RelativeMse {

    private RelativeMse() {
    }

    public static double of(FrameBuffer rendered, FrameBuffer reference) {
        requireSameSize(rendered, reference);
        float[] a = rendered.rgb(), r = reference.rgb();
        double sum = 0;
        for (int i = 0; i < a.length; i++) {
            double diff = (double) a[i] - r[i];
            sum += diff * diff / ((double) r[i] * r[i] + 0.01);
        }
        return sum / a.length;
    }

    /** Refuses two images of different sizes, which no error compares. */
    static void requireSameSize(FrameBuffer rendered, FrameBuffer reference) {
        if (rendered.width() != reference.width() || rendered.height() != reference.height()) {
            throw new IllegalArgumentException("image sizes differ: " + rendered.width() + "x" + rendered.height()
                    + " vs " + reference.width() + "x" + reference.height());
        }
    }
}
