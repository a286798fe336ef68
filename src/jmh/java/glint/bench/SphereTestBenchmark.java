package glint.bench;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.render.Intersect;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.scene.SceneLoader;
import glint.scene.SceneObject;
import glint.scene.Sphere;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The nearest-sphere query of the default scene's camera rays (its three spheres), plain Java against
 * the Vector API ({@link SphereGroup}): nanoseconds per ray. Setup checks that both give the same
 * distance and sphere, bit for bit, for every ray. Needs {@code --add-modules jdk.incubator.vector},
 * which the fork is given.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(value = 1, jvmArgsAppend = "--add-modules=jdk.incubator.vector")
public class SphereTestBenchmark {

    private static final int RAYS = 4096;

    private double[] spheres;
    private SphereGroup group;
    private Vector3d eye;
    private final double[] directions = new double[3 * RAYS];
    private int hitSphere;

    @Setup(Level.Trial)
    public void setUp() throws InputException {
        Scene scene = SceneLoader.load(Path.of("scenes/default.yaml"));
        spheres = scene.objects().stream().map(SceneObject::shape).filter(Sphere.class::isInstance)
                .map(Sphere.class::cast)
                .flatMapToDouble(s -> Arrays.stream(new double[] {s.center().x(), s.center().y(), s.center().z(),
                        s.radius()}))
                .toArray();
        group = new SphereGroup(spheres);
        Camera camera = scene.camera();
        eye = camera.position();
        double halfWidth = Math.tan(Math.toRadians(camera.fovDegrees() / 2));
        SplittableRandom random = new SplittableRandom(7);
        for (int i = 0; i < RAYS; i++) { // camera rays through random points of a 4:3 image
            double x = (2 * random.nextDouble() - 1) * halfWidth;
            double y = (2 * random.nextDouble() - 1) * halfWidth * 0.75;
            Vector3d d = camera.orientation().forward().add(camera.orientation().right().scale(x))
                    .add(camera.orientation().up().scale(y)).normalize();
            directions[3 * i] = d.x();
            directions[3 * i + 1] = d.y();
            directions[3 * i + 2] = d.z();
        }
        checkSameAnswers();
    }

    private void checkSameAnswers() {
        for (int i = 0; i < RAYS; i++) {
            double plain = plainNearest(i);
            int plainSphere = hitSphere;
            double vector = vectorNearest(i);
            if (Double.doubleToLongBits(plain) != Double.doubleToLongBits(vector) || plainSphere != hitSphere) {
                throw new IllegalStateException("ray " + i + ": plain " + plain + " (sphere " + plainSphere
                        + "), vector " + vector + " (sphere " + hitSphere + ")");
            }
        }
    }

    private double plainNearest(int ray) {
        double dx = directions[3 * ray], dy = directions[3 * ray + 1], dz = directions[3 * ray + 2];
        double nearest = Intersect.MISS;
        hitSphere = -1;
        for (int i = 0, n = spheres.length / 4; i < n; i++) {
            int k = 4 * i;
            double t = Intersect.sphereBefore(spheres[k], spheres[k + 1], spheres[k + 2], spheres[k + 3],
                    eye.x(), eye.y(), eye.z(), dx, dy, dz, nearest);
            if (t < nearest) {
                nearest = t;
                hitSphere = i;
            }
        }
        return nearest;
    }

    private double vectorNearest(int ray) {
        double t = group.nearest(eye.x(), eye.y(), eye.z(), directions[3 * ray], directions[3 * ray + 1],
                directions[3 * ray + 2], Intersect.MISS);
        hitSphere = group.hitSphere;
        return t;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public double plain() {
        double sum = 0;
        for (int i = 0; i < RAYS; i++) {
            double t = plainNearest(i);
            sum += t < Intersect.MISS ? t : 0;
        }
        return sum;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public double vector() {
        double sum = 0;
        for (int i = 0; i < RAYS; i++) {
            double t = vectorNearest(i);
            sum += t < Intersect.MISS ? t : 0;
        }
        return sum;
    }
}
