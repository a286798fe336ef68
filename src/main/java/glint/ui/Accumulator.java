package glint.ui;

import glint.render.FrameBuffer;

/**
 * Progressive refinement while the camera is still: adds the sample passes of one view and keeps
 * their plain average, which after all passes is the still image (SPEC section 3).
 */
final class Accumulator {

    private FrameBuffer mean;
    private double[] sum;
    private int passes;

    /** Starts over for a width x height view. */
    void reset(int width, int height) {
        if (mean == null || mean.width() != width || mean.height() != height) {
            mean = new FrameBuffer(width, height);
            sum = new double[3 * width * height];
        } else {
            java.util.Arrays.fill(sum, 0);
        }
        passes = 0;
    }

    /** Passes added since the last reset. */
    int passes() {
        return passes;
    }

    /** Adds one pass (of the size given to {@link #reset}) and returns the average so far. */
    FrameBuffer add(FrameBuffer pass) {
        float[] in = pass.rgb();
        float[] out = mean.rgb();
        passes++;
        double inverse = 1.0 / passes;
        for (int i = 0; i < in.length; i++) {
            sum[i] += in[i];
            out[i] = (float) (sum[i] * inverse);
        }
        return mean;
    }
}
