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
 * Two clocks: wall time, and the CPU time all threads spent (the render threads together), which
 * outside load inflates far less than wall time.
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

    /** Median times of one job, ms. */
    public record Times(double wallMillis, double cpuMillis) {
    }

    /** Median wall and CPU time of each job, in the order given; each job's frame holds its image after. */
    public Times[] median(List<Job> jobs) {
        for (Job job : jobs) {
            render(job);
        }
        double[][] wall = new double[jobs.size()][rounds];
        double[][] cpu = new double[jobs.size()][rounds];
        for (int r = 0; r < rounds; r++) {
            for (int j = 0; j < jobs.size(); j++) {
                long cpuStart = processCpuNanos();
                long start = System.nanoTime();
                render(jobs.get(j));
                wall[j][r] = (System.nanoTime() - start) / 1e6;
                cpu[j][r] = (processCpuNanos() - cpuStart) / 1e6;
            }
        }
        Times[] medians = new Times[jobs.size()];
        for (int j = 0; j < jobs.size(); j++) {
            medians[j] = new Times(median(wall[j]), median(cpu[j]));
        }
        return medians;
    }

    /**
     * CPU time of all live JVM threads so far, ns (render workers, and the little that JIT and GC
     * add), read per thread, which Linux reports to the nanosecond where the process total comes in
     * 10 ms steps; wall time if the platform does not measure thread CPU time.
     */
    static long processCpuNanos() {
        java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
        if (!threads.isThreadCpuTimeSupported()) {
            return System.nanoTime();
        }
        if (!threads.isThreadCpuTimeEnabled()) {
            threads.setThreadCpuTimeEnabled(true);
        }
        long sum = 0;
        for (long id : threads.getAllThreadIds()) {
            long t = threads.getThreadCpuTime(id);
            if (t > 0) {
                sum += t;
            }
        }
        return sum;
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
