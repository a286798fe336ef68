package glint.bench;

import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.scene.Scene;
import glint.scene.SceneLoader;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The plain path beside the SIMD one (camera rays in packets of four through the Vector API) on
 * the scenes it applies to, those without a hierarchy: the default scene and 5 matte spheres;
 * 800x600, 1 sample per pixel, depth 5, 2 threads. The fork loads the Vector API module.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(value = 1, jvmArgsAppend = "--add-modules=jdk.incubator.vector")
public class SimdBenchmark {

    @Param({"default", "matte-5"})
    public String scene;

    @Param({"plain", "simd"})
    public String path;

    private BenchFrames frames;

    @Setup(Level.Trial)
    public void setUp() throws InputException {
        Scene rendered = scene.equals("default") ? SceneLoader.load(Path.of("scenes/default.yaml"))
                : SceneLoader.parse(scene, BenchScenes.row(5, "matte"));
        frames = new BenchFrames(rendered, BenchScenes.SETTINGS.withSimd(path.equals("simd")), 2);
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        frames.close();
    }

    @Benchmark
    public FrameBuffer renderFrame() {
        return frames.render();
    }
}
