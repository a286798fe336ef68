package glint.bench;

import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.render.PlainTracer;
import glint.render.RenderScene;
import glint.render.Tracer;
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
 * The default scene's frame from {@link PlainTracer}, the yardstick, at 800x600, 1 sample per pixel,
 * depth 5, cook-torrance, 1 and 2 threads: beside {@code SceneBenchmark}'s default scene, how much
 * of Glint's frame time its culling, staging and chords save. Setup checks that the yardstick
 * renders Glint's image. {@link PairedFrames} measures the same ratio frame for frame.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class PlainTracerBenchmark {

    @Param({"1", "2"})
    public int threads;

    private PlainTracer plain;
    private final FrameBuffer frame = new FrameBuffer(PairedFrames.WIDTH, PairedFrames.HEIGHT);

    @Setup(Level.Trial)
    public void setUp() throws InputException {
        RenderScene scene = RenderScene.compile(SceneLoader.load(Path.of("scenes/default.yaml")), BenchScenes.SETTINGS);
        plain = new PlainTracer(scene, threads);
        FrameBuffer glintFrame = new FrameBuffer(PairedFrames.WIDTH, PairedFrames.HEIGHT);
        try (Tracer glint = new Tracer(threads)) {
            glint.render(scene, glintFrame, 1, 0, 8);
        }
        plain.render(frame);
        int differing = PairedFrames.differingPixels(glintFrame, frame);
        if (differing > 0) {
            throw new IllegalStateException(differing + " pixels of the plain tracer's frame differ from Glint's");
        }
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        plain.close();
    }

    @Benchmark
    public FrameBuffer renderFrame() {
        plain.render(frame);
        return frame;
    }
}
