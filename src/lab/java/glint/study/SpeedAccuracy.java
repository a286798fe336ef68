package glint.study;

import glint.config.Shading;
import glint.image.PfmReader;
import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The speed/accuracy study: renders each study scene under many configurations, times each (median
 * of several frames after warm-up) and measures its error against Glint's reference mode (relative
 * MSE and SSIM), then writes images/accuracy.png, images/accuracy-ssim.png and the tables of
 * accuracy.md into an output folder. Run from the repository root, with the lab jar built
 * (docs/benchmarks.md):
 *
 * <pre>java -cp target/benchmarks.jar glint.study.SpeedAccuracy [--quick] [--runs N] [--threads T] [--fresh] [--docs | --out DIR]</pre>
 *
 * --quick: 200 x 150, reference at 64 samples, 3 rounds, 10 configurations (under a minute on 2 cores);
 * the default: 400 x 300, reference at 1024 samples, 9 rounds, 21 configurations (a few minutes).
 * --fresh renders the references again (cached in target/study-cache). The output goes to target/study/
 * (target/study-quick/ with --quick); --docs updates docs/ itself, --out DIR chooses another folder.
 */
public final class SpeedAccuracy {

    private SpeedAccuracy() {
    }

    public static void main(String[] args) throws Exception {
        boolean quick = false, fresh = false;
        int runs = -1, threads = Runtime.getRuntime().availableProcessors();
        Path root = Path.of(".");
        Path out = null;
        boolean docs = false;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--quick" -> quick = true;
                case "--fresh" -> fresh = true;
                case "--runs" -> runs = Integer.parseInt(args[++i]);
                case "--threads" -> threads = Integer.parseInt(args[++i]);
                case "--root" -> root = Path.of(args[++i]);
                case "--out" -> out = Path.of(args[++i]);
                case "--docs" -> docs = true;
                default -> {
                    System.err.println("usage: SpeedAccuracy [--quick] [--runs N] [--threads T] [--fresh] [--root DIR] [--docs | --out DIR]");
                    System.exit(2);
                }
            }
        }
        if (docs && out != null) {
            System.err.println("SpeedAccuracy: --docs and --out both choose the output folder; give one");
            System.exit(2);
        }
        out = output(root, quick, docs, out);
        int width = quick ? 200 : 400, height = quick ? 150 : 300;
        int referenceSamples = quick ? 64 : 1024;
        if (runs < 0) {
            runs = quick ? 3 : 9;
        }
        List<StudyConfig> configs = quick ? StudyConfigs.quick() : StudyConfigs.full();
        List<StudyScene> scenes = scenes(root);
        Path cache = root.resolve("target/study-cache");

        StringBuilder meta = new StringBuilder();
        meta.append(String.format(Locale.ROOT, "Generated %s by `java -cp target/benchmarks.jar glint.study.SpeedAccuracy%s` "
                        + "on %d cores (%s, shared with other work; load average %.2f at the start), "
                        + "%d render threads, %dx%d pixels, median of %d frames per configuration (timed in turn, round by round, "
                        + "after one untimed round; CPU time is the sum over the JVM's threads, i.e. all render threads together); "
                        + "reference: cook-torrance, exact Fresnel, depth 64, plain cut-off at min_weight 1e-4, %d stratified samples.%n",
                LocalDate.now(), (quick ? " --quick" : "") + (docs ? " --docs" : ""), Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), threads, width, height, runs,
                referenceSamples));
        System.out.print(meta);

        List<List<Measurement>> perScene = new ArrayList<>();
        StringBuilder validation = new StringBuilder();
        try (Tracer tracer = new Tracer(threads)) {
            warmUp(tracer, scenes.get(0), width, height);
            ReferenceImages references = new ReferenceImages(cache, tracer, fresh);
            FrameTimer timer = new FrameTimer(tracer, runs);
            for (StudyScene scene : scenes) {
                System.out.println("scene " + scene.name());
                FrameBuffer reference = references.get(scene, StudyConfig.reference(referenceSamples), width, height);
                if (!quick && scene.hasIndependentReference()) {
                    validation.append(validate(scene, references, referenceSamples, tracer));
                }
                List<FrameTimer.Job> jobs = new ArrayList<>();
                for (StudyConfig config : configs) {
                    jobs.add(new FrameTimer.Job(RenderScene.compile(scene.scene(), config.settings()),
                            new FrameBuffer(width, height), config.samples()));
                }
                FrameTimer.Times[] times = timer.median(jobs);
                List<Measurement> results = new ArrayList<>();
                for (int c = 0; c < configs.size(); c++) {
                    FrameBuffer frame = jobs.get(c).frame();
                    Measurement m = new Measurement(scene.name(), configs.get(c), times[c].wallMillis(),
                            times[c].cpuMillis(), RelativeMse.of(frame, reference), Ssim.of(frame, reference));
                    System.out.printf(Locale.ROOT, "  %-22s %8.1f ms wall %8.1f ms CPU  relMSE %.3e  SSIM %.4f%n",
                            m.config().label(), m.millis(), m.cpuMillis(), m.relMse(), m.ssim());
                    results.add(m);
                }
                perScene.add(results);
            }
        }
        meta.append(String.format(Locale.ROOT, "Load average at the end: %.2f.%n",
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage()));
        write(out, scenes, perScene, meta.toString(), validation.toString());
    }

    /** The output folder: the one given, else docs/ with --docs, else target/study (target/study-quick with --quick). */
    static Path output(Path root, boolean quick, boolean docs, Path out) {
        if (out != null) {
            return out;
        }
        return root.resolve(docs ? "docs" : quick ? "target/study-quick" : "target/study");
    }

    /**
     * The default scene, the two scenes that have an independent (Mitsuba) reference, and clear glass
     * on a mirror floor (src/test/resources/scenes), whose light takes the most bounces.
     */
    static List<StudyScene> scenes(Path root) throws IOException, InputException {
        Path refs = root.resolve("src/test/resources/reference");
        return List.of(
                StudyScene.load("default", root.resolve("scenes/bench/spec-example.yaml"), null),
                StudyScene.load("three-spheres", refs.resolve("three-spheres.yaml"), refs.resolve("three-spheres.pfm")),
                StudyScene.load("hall-of-mirrors", refs.resolve("hall-of-mirrors.yaml"),
                        refs.resolve("hall-of-mirrors.pfm")),
                StudyScene.load("glass-on-mirror", root.resolve("src/test/resources/scenes/glass-on-mirror.yaml"), null));
    }

    /** A few frames so that the JIT has compiled the render loop before anything is timed. */
    private static void warmUp(Tracer tracer, StudyScene scene, int width, int height) {
        RenderScene compiled = RenderScene.compile(scene.scene(), StudyConfig.shipped().settings());
        FrameBuffer frame = new FrameBuffer(width, height);
        for (int i = 0; i < 8; i++) {
            tracer.render(compiled, frame, 4, 0, FrameTimer.DIVIDER);
        }
    }

    /**
     * Checks the reference mode against the independent renderer (depth 5, as it was rendered): Glint at
     * the README's settings (16 samples) and Glint's reference mode at depth 5.
     */
    private static String validate(StudyScene scene, ReferenceImages references, int referenceSamples, Tracer tracer)
            throws IOException {
        FrameBuffer mitsuba = PfmReader.read(scene.independentReference());
        int w = mitsuba.width(), h = mitsuba.height();
        FrameBuffer glint16 = new FrameBuffer(w, h);
        RenderSettings readme = new RenderSettings(Shading.COOK_TORRANCE, 5, StudyConfig.shipped().minWeight(),
                glint.config.Config.defaults().epsilon());
        tracer.render(RenderScene.compile(scene.scene(), readme), glint16, 16, 0, FrameTimer.DIVIDER);
        StudyConfig depth5 = new StudyConfig(Shading.COOK_TORRANCE, 5, referenceSamples, 0,
                RenderSettings.GlassFresnel.EXACT);
        FrameBuffer converged = references.get(scene, depth5, w, h);
        String row = String.format(Locale.ROOT, "| %s | %s | %s | %.4f |%n", scene.name(),
                Numbers.sig3(RelativeMse.of(glint16, mitsuba)), Numbers.sig3(RelativeMse.of(converged, mitsuba)),
                Ssim.of(converged, mitsuba));
        System.out.print("  against the independent reference: " + row);
        return row;
    }

    private static void write(Path out, List<StudyScene> scenes, List<List<Measurement>> perScene, String meta,
                              String validation) throws IOException {
        List<Measurement> mean = AccuracyReport.geometricMean(perScene);
        List<List<Measurement>> panels = new ArrayList<>(perScene);
        panels.add(mean);
        List<String> titles = new ArrayList<>();
        for (StudyScene s : scenes) {
            titles.add(s.name());
        }
        titles.add("geometric mean over the scenes");
        Path images = out.resolve("images");
        AccuracyChart.write(panels, titles, "relative MSE", Measurement::relMse, images.resolve("accuracy.png"));
        AccuracyChart.write(panels, titles, "1 - SSIM", m -> 1 - m.ssim(), images.resolve("accuracy-ssim.png"));

        StringBuilder tables = new StringBuilder(meta).append('\n');
        for (int i = 0; i < scenes.size(); i++) {
            tables.append("#### ").append(scenes.get(i).name()).append("\n\n").append(AccuracyReport.table(perScene.get(i)))
                    .append('\n');
        }
        tables.append("#### Geometric mean over the scenes (SSIM: arithmetic mean)\n\n")
                .append(AccuracyReport.table(mean));
        Path doc = out.resolve("accuracy.md");
        GeneratedSection.write(doc, "accuracy-tables", tables.toString());
        if (!validation.isEmpty()) {
            String head = "| scene | Glint, 16 samples, depth 5 (README settings): relMSE | Glint reference mode at depth 5: "
                    + "relMSE | SSIM |\n|---|--:|--:|--:|\n";
            GeneratedSection.write(doc, "accuracy-validation", head + validation);
        }
        System.out.println("wrote " + images.resolve("accuracy.png") + ", " + images.resolve("accuracy-ssim.png")
                + " and " + doc);
    }
}
