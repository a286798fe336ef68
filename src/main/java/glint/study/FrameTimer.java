package glint.study;

import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.Tracer;
import java.util.Arrays;
import java.util.List;

/**
 * Times renders on a machine that other work shares: every job is rendered once untimed (warm-up),
 * then all jobs are timed in turn, round after round, and each job's median is taken. Interleaving
 * spreads a burst of outside load over all jobs instead of penalising the one that ran during it.
 */
public final class FrameTimer {

    /** The tile divider of the shipped config (screen_divider). */
    public static final int DIVIDER = glint.config.Config.defaults().screenDivider();

    /** One frame to time: a compiled scene, its target and its samples per pixel. */
    public record Job(RenderScene scene, FrameBuffer frame, int samples) {
    }

    private final Tracer tracer;
    private final int rounds;

    public FrameTimer(Tracer tracer, int rounds) {
        if (rounds < 1) {
            throw new IllegalArgumentException("rounds must be >= 1");
        }
        this.tracer = tracer;
        this.rounds = rounds;
    }

    /** Median wall time in ms of each job, in the order given; each job's frame holds its image after. */
    public double[] medianMillis(List<Job> jobs) {
        for (Job job : jobs) {
            render(job);
        }
        double[][] ms = new double[jobs.size()][rounds];
        for (int r = 0; r < rounds; r++) {
            for (int j = 0; j < jobs.size(); j++) {
                long start = System.nanoTime();
                render(jobs.get(j));
                ms[j][r] = (System.nanoTime() - start) / 1e6;
            }
        }
        double[] medians = new double[jobs.size()];
        for (int j = 0; j < jobs.size(); j++) {
            medians[j] = median(ms[j]);
        }
        return medians;
    }

    private void render(Job job) {
        tracer.render(job.scene(), job.frame(), job.samples(), 0, DIVIDER);
    }

    public static double median(double[] values) {
        double[] s = values.clone();
        Arrays.sort(s);
        int n = s.length;
        return n % 2 == 1 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
    }
}
