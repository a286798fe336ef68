package glint.bench;

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
 * defaults). Then a row's point-light samples (the arithmetic of {@code RowHits.samplePointLight}
 * without its branch: a square root and a division a value, fourteen arrays) in one loop, which
 * the JIT leaves scalar with its default {@code -XX:LoopUnrollLimit=60} (its body is too big to
 * unroll, and a loop it does not unroll it does not vectorise), in a fork with the limit raised,
 * and in five loops small enough for the default limit, which setup checks give the same values
 * bit for bit. docs/benchmarks.md, "What limits the next factor of two".
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
    private final LightSamples samples = new LightSamples(VALUES);

    @Setup
    public void setUp() {
        SplittableRandom random = new SplittableRandom(22);
        for (int i = 0; i < VALUES; i++) {
            in[i] = 1 + 100 * random.nextDouble();
        }
        samples.fill(random);
        samples.checkBothWaysAgree();
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
        return samples.sample(-5, 8, -6, 100, 90, 80);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    @Fork(value = 1, jvmArgsAppend = "-XX:LoopUnrollLimit=250")
    public double[] pointLightSamplesUnrollLimit250() {
        return samples.sample(-5, 8, -6, 100, 90, 80);
    }

    @Benchmark
    @OperationsPerInvocation(VALUES)
    public double[] pointLightSamplesInSmallLoops() {
        return samples.sampleInSmallLoops(-5, 8, -6, 100, 90, 80);
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

    /** A row's matte hits and their samples of a point light, one coordinate an array, as in {@code RowHits}. */
    private static final class LightSamples {
        final double[] px, py, pz, nx, ny, nz;
        final double[] toLightX, toLightY, toLightZ, distance, cosLight, lightR, lightG, lightB;
        final double[] inverseDistance;

        LightSamples(int count) {
            px = new double[count];
            py = new double[count];
            pz = new double[count];
            nx = new double[count];
            ny = new double[count];
            nz = new double[count];
            toLightX = new double[count];
            toLightY = new double[count];
            toLightZ = new double[count];
            distance = new double[count];
            cosLight = new double[count];
            lightR = new double[count];
            lightG = new double[count];
            lightB = new double[count];
            inverseDistance = new double[count];
        }

        /** Throws unless {@link #sample} and {@link #sampleInSmallLoops} give the same values bit for bit. */
        void checkBothWaysAgree() {
            double[][] outputs = {toLightX, toLightY, toLightZ, distance, cosLight, lightR, lightG, lightB};
            sample(-5, 8, -6, 100, 90, 80);
            double[][] inOneLoop = new double[outputs.length][];
            for (int k = 0; k < outputs.length; k++) {
                inOneLoop[k] = outputs[k].clone();
            }
            sampleInSmallLoops(-5, 8, -6, 100, 90, 80);
            for (int k = 0; k < outputs.length; k++) {
                if (!Arrays.equals(inOneLoop[k], outputs[k])) {
                    throw new IllegalStateException("the light samples in small loops differ from those in one, array " + k);
                }
            }
        }

        /** Points on a floor in front of the default scene's camera, normals up. */
        void fill(SplittableRandom random) {
            for (int j = 0; j < px.length; j++) {
                px[j] = 8 * random.nextDouble() - 4;
                pz[j] = 10 * random.nextDouble() - 2;
                ny[j] = 1;
            }
        }

        /** The sample of a point light at (x, y, z) of power (powerR, powerG, powerB) at every point. */
        double[] sample(double x, double y, double z, double powerR, double powerG, double powerB) {
            double[] px = this.px, py = this.py, pz = this.pz, nx = this.nx, ny = this.ny, nz = this.nz;
            double[] toLightX = this.toLightX, toLightY = this.toLightY, toLightZ = this.toLightZ;
            double[] distance = this.distance, cosLight = this.cosLight;
            double[] lightR = this.lightR, lightG = this.lightG, lightB = this.lightB;
            for (int j = 0; j < px.length; j++) {
                double lx = x - px[j], ly = y - py[j], lz = z - pz[j];
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
                lightR[j] = powerR * scale * cos;
                lightG[j] = powerG * scale * cos;
                lightB[j] = powerB * scale * cos;
            }
            return lightR;
        }
    
        /**
         * {@link #sample} in loops small enough for the JIT to unroll and vectorise with its default
         * limit: the same arithmetic for each point, so the same values bit for bit.
         */
        double[] sampleInSmallLoops(double x, double y, double z, double powerR, double powerG, double powerB) {
            double[] px = this.px, py = this.py, pz = this.pz, inv = this.inverseDistance;
            int count = px.length;
            for (int j = 0; j < count; j++) {
                double lx = x - px[j], ly = y - py[j], lz = z - pz[j];
                inv[j] = 1 / Math.sqrt(lx * lx + ly * ly + lz * lz);
            }
            for (int j = 0; j < count; j++) {
                double lx = x - px[j], ly = y - py[j], lz = z - pz[j];
                distance[j] = (lx * lx + ly * ly + lz * lz) * inv[j];
            }
            double[] toLightX = this.toLightX, toLightY = this.toLightY, toLightZ = this.toLightZ;
            for (int j = 0; j < count; j++) {
                toLightX[j] = (x - px[j]) * inv[j];
                toLightY[j] = (y - py[j]) * inv[j];
                toLightZ[j] = (z - pz[j]) * inv[j];
            }
            double[] nx = this.nx, ny = this.ny, nz = this.nz, cosLight = this.cosLight;
            for (int j = 0; j < count; j++) {
                cosLight[j] = toLightX[j] * nx[j] + toLightY[j] * ny[j] + toLightZ[j] * nz[j];
            }
            double[] lightR = this.lightR, lightG = this.lightG, lightB = this.lightB;
            for (int j = 0; j < count; j++) {
                double scale = inv[j] * inv[j], cos = cosLight[j];
                lightR[j] = powerR * scale * cos;
                lightG[j] = powerG * scale * cos;
                lightB[j] = powerB * scale * cos;
            }
            return lightR;
        }
    }
}
