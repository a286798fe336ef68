package glint.render;

import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * What square roots and divisions cost the renderer's loops, in nanoseconds a value over a row of
 * {@value #VALUES} independent values: each one at a time (a fork with {@code -XX:-UseSuperWord}),
 * and as the SIMD instructions the JIT makes of a small branch-free loop (a fork with the JVM's
 * defaults). Then a row's point-light samples: the renderer's own {@link RowHits#samplePointLight},
 * five loops small enough for the JIT to unroll and vectorise, against the same arithmetic in one
 * loop (as the renderer had it, without its branch), which the JIT leaves scalar with its default
 * {@code -XX:LoopUnrollLimit=60} (its body is too big to unroll, and a loop it does not unroll it
 * does not vectorise), in a fork with the JVM's defaults and one with the limit raised. Setup checks
 * that both give the same values bit for bit. In this package to reach {@code RowHits};
 * docs/benchmarks.md, "What limits the next factor of two".
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class DividerBenchmark {

    private static final int VALUES = 4096;
    private static final String SCALAR = "-XX:-UseSuperWord";

    private final double[] in = new double[VALUES], out = new double[VALUES];
    /** A row of matte hits: points on a floor in front of the default scene's camera, normals up. */
    private final RowHits hits = new RowHits();

    @Setup
    public void setUp() {
        SplittableRandom random = new SplittableRandom(22);
        for (int i = 0; i < VALUES; i++) {
            in[i] = 1 + 100 * random.nextDouble();
        }
        hits.fit(VALUES);
        for (int j = 0; j < VALUES; j++) {
            hits.px[j] = 8 * random.nextDouble() - 4;
            hits.pz[j] = 10 * random.nextDouble() - 2;
            hits.ny[j] = 1;
        }
        checkBothWaysAgree();
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    public double[] squareRootsSimd() {
        return squareRoots(in, out);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    @Fork(value = 1, jvmArgsAppend = SCALAR)
    public double[] squareRootsScalar() {
        return squareRoots(in, out);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    public double[] divisionsSimd() {
        return reciprocals(in, out);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    @Fork(value = 1, jvmArgsAppend = SCALAR)
    public double[] divisionsScalar() {
        return reciprocals(in, out);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    public double[] inverseSquareRootsSimd() {
        return inverseSquareRoots(in, out);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    @Fork(value = 1, jvmArgsAppend = SCALAR)
    public double[] inverseSquareRootsScalar() {
        return inverseSquareRoots(in, out);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    public double[] pointLightSamples() {
        return sampleInOneLoop(hits);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    @Fork(value = 1, jvmArgsAppend = "-XX:LoopUnrollLimit=250")
    public double[] pointLightSamplesUnrollLimit250() {
        return sampleInOneLoop(hits);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    public double[] pointLightSamplesInSmallLoops() {
        hits.samplePointLight(VALUES, LIGHT_X, LIGHT_Y, LIGHT_Z, POWER_R, POWER_G, POWER_B);
        return hits.lightR;
    }

    private static double[] squareRoots(double[] in, double[] out) {
        for (int i = 0; i < in.length; i++) {
            out[i] = Math.sqrt(in[i]);
        }
        return out;
    }

    private static double[] reciprocals(double[] in, double[] out) {
        for (int i = 0; i < in.length; i++) {
            out[i] = 1 / in[i];
        }
        return out;
    }

    private static double[] inverseSquareRoots(double[] in, double[] out) {
        for (int i = 0; i < in.length; i++) {
            out[i] = 1 / Math.sqrt(in[i]);
        }
        return out;
    }

    // the default scene's light
    private static final double LIGHT_X = -5, LIGHT_Y = 8, LIGHT_Z = -6, POWER_R = 100, POWER_G = 90, POWER_B = 80;

    /**
     * The point-light samples of every hit of the row in one loop: the arithmetic of
     * {@link RowHits#samplePointLight}, for each hit in the same order, without its five loops.
     */
    private static double[] sampleInOneLoop(RowHits h) {
        double[] px = h.px, py = h.py, pz = h.pz, nx = h.nx, ny = h.ny, nz = h.nz;
        double[] toLightX = h.toLightX, toLightY = h.toLightY, toLightZ = h.toLightZ;
        double[] distance = h.lightDistance, cosLight = h.cosLight, lightR = h.lightR, lightG = h.lightG,
                lightB = h.lightB;
        for (int j = 0; j < VALUES; j++) {
            double lx = LIGHT_X - px[j], ly = LIGHT_Y - py[j], lz = LIGHT_Z - pz[j];
            double distance2 = lx * lx + ly * ly + lz * lz;
            double inv = 1 / Math.sqrt(distance2);
            double ux = lx * inv, uy = ly * inv, uz = lz * inv;
            double scale = inv * inv;
            double cos = ux * nx[j] + uy * ny[j] + uz * nz[j];
            cosLight[j] = cos;
            toLightX[j] = ux;
            toLightY[j] = uy;
            toLightZ[j] = uz;
            distance[j] = distance2 * inv;
            lightR[j] = POWER_R * scale * cos;
            lightG[j] = POWER_G * scale * cos;
            lightB[j] = POWER_B * scale * cos;
        }
        return lightR;
    }

    /** Throws unless {@link #sampleInOneLoop} and {@link RowHits#samplePointLight} give the same values bit for bit. */
    private void checkBothWaysAgree() {
        sampleInOneLoop(hits);
        double[][] inOneLoop = outputs();
        hits.samplePointLight(VALUES, LIGHT_X, LIGHT_Y, LIGHT_Z, POWER_R, POWER_G, POWER_B);
        double[][] inSmallLoops = outputs();
        for (int k = 0; k < inOneLoop.length; k++) {
            if (!Arrays.equals(inOneLoop[k], inSmallLoops[k])) {
                throw new IllegalStateException("the light samples in small loops differ from those in one, array " + k);
            }
        }
    }

    /** Copies of the samples' arrays. */
    private double[][] outputs() {
        RowHits h = hits;
        double[][] arrays = {h.toLightX, h.toLightY, h.toLightZ, h.lightDistance, h.cosLight, h.lightR, h.lightG,
                h.lightB};
        for (int k = 0; k < arrays.length; k++) {
            arrays[k] = arrays[k].clone();
        }
        return arrays;
    }
}
