package glint.study;

import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.render.RenderScene;
import glint.render.Tracer;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The speed/accuracy study: renders each study scene with every method (ray casting, Whitted at
 * several depths and samples, the path tracer at 1 to 1024 samples), times each in render CPU and
 * measures its error against the scene's converged path-traced image (relative MSE, SSIM, FLIP, the
 * 8-bit error), which it checks against an independent path tracer's images first; Whitted's
 * configurations are also measured against Whitted's own converged image. It writes one chart per
 * scene (images/accuracy-SCENE.png), images/accuracy-whitted.png and the tables of accuracy.md into an
 * output folder. Run from the repository root, with the lab jar built (docs/benchmarks.md):
 *
 * <pre>java -cp target/benchmarks.jar glint.study.SpeedAccuracy [--quick] [--runs N] [--threads T] [--fresh] [--scene NAME] [--docs | --out DIR]</pre>
 *
 * The default: 200 x 150, references at 4096 (path) and 1024 (Whitted) samples, 5 rounds; --quick:
 * 100 x 75, references at 256 and 64 samples, 3 rounds, fewer methods (under a minute on 2 cores).
 * --fresh renders the references again (cached in target/study-cache); --scene keeps one scene (may
 * be repeated). The output goes to target/study/ (target/study-quick/ with --quick); --docs updates
 * docs/ itself, --out DIR chooses another folder.
 */
public final class SpeedAccuracy {

    /** A run's sizes: the image, the references' samples, the timed rounds and the methods. */
    record Plan(int width, int height, int pathReferenceSamples, int whittedReferenceSamples, int runs,
                List<StudyConfig> configs, boolean quick) {
        static Plan of(boolean quick, int runs) {
            return quick ? new Plan(100, 75, 256, 64, runs < 0 ? 3 : runs, StudyConfigs.quick(), true)
                    : new Plan(200, 150, 4096, 1024, runs < 0 ? 5 : runs, StudyConfigs.full(), false);
        }
    }

    /** One scene's results: against the path-traced reference (the methods) and against Whitted's own. */
    record SceneResult(StudyScene scene, List<Measurement> physics, List<Measurement> whitted, String validation) {
    }

    private SpeedAccuracy() {
    }

    public static void main(String[] args) throws Exception {
        boolean quick = false, fresh = false, docs = false;
        int runs = -1, threads = Runtime.getRuntime().availableProcessors();
        Path root = Path.of(".");
        Path out = null;
        List<String> only = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--quick" -> quick = true;
                case "--fresh" -> fresh = true;
                case "--runs" -> runs = Integer.parseInt(args[++i]);
                case "--threads" -> threads = Integer.parseInt(args[++i]);
                case "--root" -> root = Path.of(args[++i]);
                case "--out" -> out = Path.of(args[++i]);
                case "--scene" -> only.add(args[++i]);
                case "--docs" -> docs = true;
                default -> {
                    System.err.println("usage: SpeedAccuracy [--quick] [--runs N] [--threads T] [--fresh] [--scene NAME] "
                            + "[--root DIR] [--docs | --out DIR]");
                    System.exit(2);
                }
            }
        }
        if (docs && out != null) {
            System.err.println("SpeedAccuracy: --docs and --out both choose the output folder; give one");
            System.exit(2);
        }
        if (docs && !only.isEmpty()) {
            System.err.println("SpeedAccuracy: --scene leaves scenes out of the tables; run --docs with all of them");
            System.exit(2);
        }
        long start = System.nanoTime();
        List<StudyScene> scenes = select(scenes(root), only);
        Plan plan = Plan.of(quick, runs);
        String meta = header(plan, threads, quick, docs);
        System.out.print(meta);
        List<SceneResult> results = run(plan, scenes, root.resolve("target/study-cache"), threads, fresh);
        String end = String.format(Locale.ROOT, "Load average at the end: %.2f; the run took %.1f minutes.%n",
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), (System.nanoTime() - start) / 6e10);
        System.out.print(end);
        StudyOutput.write(output(root, quick, docs, out), results, meta + end);
    }

    /** Renders, times and measures every scene of the plan. */
    static List<SceneResult> run(Plan plan, List<StudyScene> scenes, Path cache, int threads, boolean fresh)
            throws IOException {
        List<SceneResult> results = new ArrayList<>();
        try (Tracer tracer = new Tracer(threads)) {
            warmUp(tracer, scenes.get(0), plan);
            ReferenceImages references = new ReferenceImages(cache, tracer, fresh);
            FrameTimer timer = new FrameTimer(tracer, plan.runs());
            for (StudyScene scene : scenes) {
                System.out.println("scene " + scene.name());
                results.add(measure(scene, plan, references, timer));
            }
        }
        return results;
    }

    private static SceneResult measure(StudyScene scene, Plan plan, ReferenceImages references, FrameTimer timer)
            throws IOException {
        int w = plan.width(), h = plan.height();
        FrameBuffer physics = references.get(scene, StudyConfig.pathReference(plan.pathReferenceSamples()), w, h);
        FrameBuffer whitted = references.get(scene, StudyConfig.reference(plan.whittedReferenceSamples()), w, h);
        String validation = scene.hasIndependentReference()
                ? PhysicsValidation.rows(scene, physics, plan.pathReferenceSamples(), whitted, references, !plan.quick())
                : "";
        System.out.print(validation);
        List<FrameTimer.Job> jobs = new ArrayList<>();
        for (StudyConfig config : plan.configs()) {
            jobs.add(new FrameTimer.Job(RenderScene.compile(scene.scene(), config.settings()), new FrameBuffer(w, h),
                    config.samples()));
        }
        FrameTimer.Times[] times = timer.median(jobs);
        List<StudyConfig> methods = StudyConfigs.methods();
        List<Measurement> againstPhysics = new ArrayList<>(), againstWhitted = new ArrayList<>();
        for (int c = 0; c < jobs.size(); c++) {
            StudyConfig config = plan.configs().get(c);
            FrameBuffer frame = jobs.get(c).frame();
            Measurement m = new Measurement(scene.name(), config, times[c].wallMillis(), times[c].cpuMillis(),
                    ImageErrors.of(frame, physics));
            if (methods.contains(config)) {
                againstPhysics.add(m);
            }
            if (StudyConfigs.againstWhitted(config)) {
                againstWhitted.add(new Measurement(scene.name(), config, m.millis(), m.cpuMillis(),
                        ImageErrors.of(frame, whitted)));
            }
            System.out.printf(Locale.ROOT, "  %-22s %9.1f ms wall %9.1f ms CPU  relMSE %.3e  SSIM %.4f  FLIP %.4f%n",
                    config.label(), m.millis(), m.cpuMillis(), m.relMse(), m.ssim(), m.flip());
        }
        return new SceneResult(scene, againstPhysics, againstWhitted, validation);
    }

    /** The output folder: the one given, else docs/ with --docs, else target/study (target/study-quick with --quick). */
    static Path output(Path root, boolean quick, boolean docs, Path out) {
        if (out != null) {
            return out;
        }
        return root.resolve(docs ? "docs" : quick ? "target/study-quick" : "target/study");
    }

    /**
     * The two scenes with an independent path-traced reference (src/test/resources/reference-pt) and
     * the shipped ones: the default scene, five matte balls, the metals and the glass.
     */
    static List<StudyScene> scenes(Path root) throws IOException, InputException {
        List<StudyScene> scenes = new ArrayList<>(PhysicsValidation.scenes(root));
        Path shipped = root.resolve("scenes");
        scenes.add(StudyScene.load("default", shipped.resolve("default.yaml"), null));
        for (String name : List.of("report-matte", "metals", "glass")) {
            scenes.add(StudyScene.load(name, shipped.resolve(name + ".yaml"), null));
        }
        return scenes;
    }

    /** The scenes named in {@code only} (all of them if it is empty). */
    static List<StudyScene> select(List<StudyScene> scenes, List<String> only) {
        if (only.isEmpty()) {
            return scenes;
        }
        List<StudyScene> kept = new ArrayList<>();
        for (String name : only) {
            StudyScene found = null;
            for (StudyScene s : scenes) {
                if (s.name().equals(name)) {
                    found = s;
                }
            }
            if (found == null) {
                List<String> names = new ArrayList<>();
                scenes.forEach(s -> names.add(s.name()));
                throw new IllegalArgumentException("no study scene '" + name + "'; the scenes are " + names);
            }
            kept.add(found);
        }
        return kept;
    }

    private static String header(Plan plan, int threads, boolean quick, boolean docs) {
        return String.format(Locale.ROOT, "Generated %s by `java -cp target/benchmarks.jar glint.study.SpeedAccuracy%s` "
                        + "on %d cores (%s, shared with other work; load average %.2f at the start), %d render threads, "
                        + "%dx%d pixels; render CPU is the CPU time of the render threads together, the median of %d "
                        + "frames timed in turn, round by round, after one untimed frame (a first frame of %.0f s of CPU "
                        + "or more is its only one); references: path, depth %d, %d samples, and Whitted, cook-torrance, "
                        + "exact Fresnel, depth %d, plain cut-off at min_weight 1e-4, %d samples.%n",
                LocalDate.now(), (quick ? " --quick" : "") + (docs ? " --docs" : ""), Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), threads, plan.width(), plan.height(),
                plan.runs(), FrameTimer.LONG_FRAME_CPU_MILLIS / 1000, StudyConfig.REFERENCE_DEPTH,
                plan.pathReferenceSamples(), StudyConfig.REFERENCE_DEPTH, plan.whittedReferenceSamples());
    }

    /** A few frames of each integrator so that the JIT has compiled both render loops before anything is timed. */
    private static void warmUp(Tracer tracer, StudyScene scene, Plan plan) {
        FrameBuffer frame = new FrameBuffer(plan.width(), plan.height());
        for (StudyConfig config : List.of(StudyConfig.shipped(), StudyConfig.path(1))) {
            RenderScene compiled = RenderScene.compile(scene.scene(), config.settings());
            for (int i = 0; i < 8; i++) {
                tracer.render(compiled, frame, 4, 0, FrameTimer.DIVIDER);
            }
        }
    }
}
