package glint.bench;

import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.render.LightTransport;
import glint.scenefile.SceneLoader;
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
 * The target scenes of docs/benchmarks.md: the spec's example scene, 25 glass spheres, 1,000 spheres;
 * and lamplight, everything with a size (a sphere lamp, a sun with an angle, frosted glass, a thin lens);
 * 800x600, 1 sample per pixel, depth 5, cook-torrance, 1 and 2 threads, Whitted's integrator and
 * the path tracer. Run with -prof gc to see the allocation per frame.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class SceneBenchmark {

    @Param({"spec-example", "glass-25", "field-1000", "lamplight"})
    public String scene;

    @Param({"1", "2"})
    /** The tracer's render threads (JMH's "Threads: 1 thread" is the one thread that calls the benchmark). */
    public int renderThreads;

    @Param({"whitted", "path"})
    public String integrator;

    private BenchFrames frames;

    @Setup(Level.Trial)
    public void setUp() throws InputException {
        String text = switch (scene) {
            case "glass-25" -> BenchScenes.row(25, "glass");
            case "field-1000" -> BenchScenes.field(1000);
            default -> null;
        };
        frames = new BenchFrames(text == null ? SceneLoader.load(BenchScenes.file(scene))
                : SceneLoader.parse(scene, text), BenchScenes.SETTINGS.withTransport(LightTransport.byKey(integrator)),
                renderThreads);
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
