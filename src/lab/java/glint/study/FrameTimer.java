package glint.study;

import glint.image.FrameBuffer;
import glint.render.RenderScene;
import glint.render.Tracer;
import java.util.Arrays;
import java.util.List;

/**
 * Times renders on a machine that other work shares: every job is rendered once, in the order given
 * (cheapest first, so the JIT has compiled the render loop before the long ones), then all jobs are
 * timed in turn, round after round, and each job's median is taken. Interleaving spreads a burst of
 * outside load over all jobs instead of penalising the one that ran during it. A job whose first
 * frame took at least {@link #LONG_FRAME_CPU_MILLIS} of CPU is timed by that frame alone: its length
 * already averages the load, and repeating it would cost most of the study's time. Two clocks: wall
 * time, and the CPU time of the render threads (together), which outside load inflates far less.
 */
public final class FrameTimer {

    /** The tile divider of the shipped config (screen_divider). */
    public static final int DIVIDER = glint.config.Config.defaults().screenDivider();

    /** One frame to time: a compiled scene, its target and its samples per pixel. */
    public record Job(RenderScene scene, FrameBuffer frame, int samples) {
    }

    /** A first frame at least this long (render CPU, ms) is the job's only timed one. */
    public static final double LONG_FRAME_CPU_MILLIS = 2000;

    private final Tracer tracer;
    private final int rounds;
    private final double longFrameCpuMillis;

    public FrameTimer(Tracer tracer, int rounds) {
        this(tracer, rounds, LONG_FRAME_CPU_MILLIS);
    }

    /** Times with {@code rounds} rounds; a first frame of at least {@code longFrameCpuMillis} is its job's only one. */
    public FrameTimer(Tracer tracer, int rounds, double longFrameCpuMillis) {
        if (rounds < 1) {
            throw new IllegalArgumentException("rounds must be >= 1");
        }
        this.tracer = tracer;
        this.rounds = rounds;
        this.longFrameCpuMillis = longFrameCpuMillis;
    }

    /** Median times of one job, ms. */
    public record Times(double wallMillis, double cpuMillis) {
    }

    /** Median wall and CPU time of each job, in the order given; each job's frame holds its image after. */
    public Times[] median(List<Job> jobs) {
        Times[] first = new Times[jobs.size()];
        for (int j = 0; j < jobs.size(); j++) {
            first[j] = timed(jobs.get(j));
        }
        double[][] wall = new double[jobs.size()][rounds];
        double[][] cpu = new double[jobs.size()][rounds];
        for (int r = 0; r < rounds; r++) {
            for (int j = 0; j < jobs.size(); j++) {
                if (first[j].cpuMillis() < longFrameCpuMillis) {
                    Times t = timed(jobs.get(j));
                    wall[j][r] = t.wallMillis();
                    cpu[j][r] = t.cpuMillis();
                }
            }
        }
        Times[] medians = new Times[jobs.size()];
        for (int j = 0; j < jobs.size(); j++) {
            medians[j] = first[j].cpuMillis() >= longFrameCpuMillis ? first[j]
                    : new Times(median(wall[j]), median(cpu[j]));
        }
        return medians;
    }

    private Times timed(Job job) {
        long cpuStart = renderCpuNanos();
        long start = System.nanoTime();
        render(job);
        long wall = System.nanoTime() - start;
        return new Times(wall / 1e6, (renderCpuNanos() - cpuStart) / 1e6);
    }

    /** The render threads' CPU time so far (the tracer's clock), or all threads' where it has none. */
    private long renderCpuNanos() {
        long nanos = tracer.renderCpuNanos();
        return nanos >= 0 ? nanos : processCpuNanos();
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
