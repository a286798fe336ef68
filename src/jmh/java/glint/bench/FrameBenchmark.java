package glint.bench;

import glint.image.FrameBuffer;
import glint.input.InputException;
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
 * Frame time against thread count, sphere count and material (the 2020 report's figures 16 and
 * 17): 800x600, 1 sample per pixel, depth 5, cook-torrance.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 3, time = 1)
@Fork(1)
public class FrameBenchmark {

    @Param({"1", "2", "4", "8"})
    /** The tracer's render threads (JMH's "Threads: 1 thread" is the one thread that calls the benchmark). */
    public int renderThreads;

    @Param({"1", "5", "10", "15", "20", "25"})
    public int spheres;

    @Param({"matte", "glass"})
    public String material;

    private BenchFrames frames;

    @Setup(Level.Trial)
    public void setUp() throws InputException {
        frames = new BenchFrames(SceneLoader.parse("bench", BenchScenes.row(spheres, material)), BenchScenes.SETTINGS,
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
