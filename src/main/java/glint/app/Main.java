package glint.app;

import glint.config.Config;
import glint.config.ConfigLoader;
import glint.config.Flags;
import glint.config.JarCommand;
import glint.input.InputException;
import glint.still.OutputFile;
import glint.still.WriteFailure;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicBoolean;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** The command line (README.md, "Using it"): parses arguments, loads the config, hands over to a mode. */
@Command(name = "glint", mixinStandardHelpOptions = true, version = "Glint 0.1.0",
        description = "Interactive ray tracer for spheres and planes.%n"
                + "Fly through a scene in the window with Whitted's integrator (the default);%n"
                + "render stills with the path tracer (--integrator path): light that bounces;%n"
                + "with caustics (light through glass, off mirrors) with --integrator bdpt.%n"
                + "Without --output or --bench, opens the window on the scene.",
        sortOptions = false)
public final class Main implements Callable<Integer> {

    public static final int OK = 0;
    public static final int FAILURE = 1;
    public static final int BAD_INPUT = 2;
    /** Exit status when standard output's reader has gone ({@code | head -1}): 128 + SIGPIPE, as a shell reports it. */
    public static final int READER_GONE = 141;

    @Option(names = "--scene", paramLabel = "FILE", description = "scene file (default: the config's 'scene')")
    Path scene;

    @Option(names = "--config", paramLabel = "FILE", description = "config file (default: ./config.properties)")
    Path config;

    @Option(names = "--output", paramLabel = "FILE", description = "render one frame headless to FILE.png or FILE.pfm")
    Path output;

    @Option(names = "--width", paramLabel = "W", description = "image width in pixels")
    Integer width;

    @Option(names = "--height", paramLabel = "H", description = "image height in pixels")
    Integer height;

    @Option(names = "--spp", paramLabel = "N", description = "samples per pixel: 1, 4, 9, 16, ...")
    Integer spp;

    @Option(names = "--threads", paramLabel = "T", description = "render threads, 0 = one per core")
    Integer threads;

    @Option(names = "--depth", paramLabel = "D", description = "recursion_max: surface hits along a path")
    Integer depth;

    @Option(names = "--shading", paramLabel = "MODEL", description = "cook-torrance or phong")
    String shading;

    @Option(names = "--integrator", paramLabel = "NAME", description = "whitted (direct light, mirrors, glass), path (light that bounces) or bdpt (and caustics)")
    String integrator;

    @Option(names = "--exposure", paramLabel = "STOPS",
            description = "brighter (+1 doubles the light) or darker (-1 halves it) in PNGs and the window; default 0")
    Double exposure;

    @Option(names = "--tone", paramLabel = "CURVE",
            description = "neutral (highlights roll off to white, the default) or standard (clamped at white)")
    String tone;

    @Option(names = "--noise", paramLabel = "T",
            description = "path and bdpt: render each pixel until its noise is below T (0.01 = 1 %%), up to --max-samples")
    Double noise;

    @Option(names = "--max-samples", paramLabel = "N",
            description = "the most samples a pixel gets from --noise and the window's refinement; default 1024")
    Integer maxSamples;

    @Option(names = "--bench", paramLabel = "N", description = "render N frames of the still camera headless and time them")
    Integer bench;

    @Option(names = "--view", paramLabel = "N|NAME",
            description = "with --output or --bench: the scene's view N (from 1) or the view of that name, not its camera")
    String view;

    /** The parsed command line, for the file names as they were typed. */
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /** Where the modes write their report lines and diagnostics; set by {@link #run}. */
    private PrintWriter out = new PrintWriter(System.out, true);
    private PrintWriter err = new PrintWriter(System.err, true);

    public static void main(String[] args) {
        AtomicBoolean noted = new AtomicBoolean(); // a character the locale cannot show is said once
        PrintWriter err = LocaleWriter.standardError(noted);
        ThreadFailures failures = ThreadFailures.install(err); // every thread's error: one line, status 1
        Interrupts.handleOtherEndingSignals();
        System.exit(failures.status(run(args, Output.standard(noted, err), err, failures)));
    }

    /** Runs the program and returns its exit status; nothing is written but to out and err. */
    public static int run(String[] args, PrintWriter out, PrintWriter err) {
        return run(args, out, err, new ThreadFailures(err));
    }

    private static int run(String[] args, PrintWriter out, PrintWriter err, ThreadFailures failures) {
        Main main = new Main();
        main.out = out;
        main.err = err;
        CommandLine cli = new CommandLine(main);
        cli.setExpandAtFiles(false); // --scene @s.yaml is the file '@s.yaml', never a file of arguments
        // printed as it is: the parser would break a long jar path's commands in the middle of a word
        cli.getCommandSpec().usageMessage().sectionMap()
                .put(CommandLine.Model.UsageMessageSpec.SECTION_KEY_FOOTER, help -> HelpFooter.text());
        cli.setOut(out);
        cli.setErr(err);
        cli.setExecutionStrategy(parsed -> { // --help and --version, printed by the parser, can fail too
            try {
                return new CommandLine.RunLast().execute(parsed);
            } catch (Output.Failure e) {
                return outputFailed(e, err);
            }
        });
        cli.registerConverter(Integer.class, Main::wholeNumber);
        cli.registerConverter(Double.class, Main::decimalNumber);
        cli.registerConverter(Path.class, Main::fileName);
        cli.setParameterExceptionHandler((e, a) -> {
            if (e instanceof CommandLine.UnmatchedArgumentException unmatched) {
                UnknownArguments.lines(unmatched.getUnmatched(), cli.getCommandSpec())
                        .forEach(problem -> err.println(line("glint: " + problem)));
                err.println(tryHelp());
                return BAD_INPUT;
            }
            err.println(line("glint: " + e.getMessage()));
            if (String.valueOf(e.getMessage()).endsWith(FileNames.FIX)) {
                return BAD_INPUT; // the options are right: the locale is not
            }
            err.println(tryHelp());
            return BAD_INPUT;
        });
        cli.setExecutionExceptionHandler((e, c, p) -> {
            if (e instanceof InputException bad) {
                err.println(bad.getMessage());
                return BAD_INPUT;
            }
            if (e instanceof Output.Failure failure) {
                return outputFailed(failure, err);
            }
            if (e instanceof WriteFailure failure) {
                err.println(line("glint: " + failure.getMessage()));
                return FAILURE;
            }
            if (e.getCause() instanceof OutOfMemoryError) { // in a render thread
                failures.outOfMemory(e.getCause());
                return FAILURE;
            }
            if (e instanceof java.nio.file.FileSystemException fs && fs.getFile() != null) {
                err.println(line("glint: " + InputException.cutPath(fs.getFile()) + ": " + OutputFile.reason(fs)));
                return FAILURE;
            }
            err.println(line("glint: " + (e instanceof java.io.IOException && e.getMessage() != null ? e.getMessage() : e)));
            return FAILURE;
        });
        try {
            return cli.execute(args);
        } catch (OutOfMemoryError e) {
            failures.outOfMemory(e);
            return FAILURE;
        }
    }

    /** The hint after a mistake in the options, naming the jar that runs. */
    private static String tryHelp() {
        return InputException.printable("Try '" + JarCommand.java() + " --help' for the options.");
    }

    /**
     * Standard output failed: a reader that has gone ends the program quietly, as a Unix tool's
     * SIGPIPE does; any other failure is a line on standard error and status 1.
     */
    private static int outputFailed(Output.Failure failure, PrintWriter err) {
        if (failure.readerGone()) {
            return READER_GONE;
        }
        err.println(line("glint: " + failure.getMessage()));
        return FAILURE;
    }

    /** The most characters a line of a message from elsewhere (the parser, the system) is given. */
    static final int MAX_LINE = 1000;

    /**
     * A message made elsewhere as one printable line: quoted values cut as by
     * {@link InputException#quote}, and the whole cut to {@link #MAX_LINE} characters.
     */
    static String line(String message) {
        String text = InputException.printable(InputException.cutQuoted(message));
        return text.length() <= MAX_LINE ? text : text.substring(0, MAX_LINE - 3) + "...";
    }

    /** How the line that memory ran out begins, and the line itself when not even its reason can be had. */
    static final String OUT_OF_MEMORY_START = "glint: out of memory";
    static final String OUT_OF_MEMORY = OUT_OF_MEMORY_START + "; render fewer pixels, samples or threads, "
            + "or start Java with a larger -Xmx";

    static String outOfMemory(Throwable e) {
        return OUT_OF_MEMORY_START + " (" + e.getMessage() + "); render fewer pixels, samples or threads, "
                + "or start Java with a larger -Xmx";
    }

    /** An option's whole number: ASCII digits only (Java's own parser takes other scripts' digits too). */
    static Integer wholeNumber(String text) {
        if (!text.matches("[-+]?[0-9]{1,10}")) {
            throw new CommandLine.TypeConversionException(InputException.quote(text)
                    + " is not a whole number written with the digits 0-9");
        }
        long n = Long.parseLong(text);
        if (n > Integer.MAX_VALUE || n < Integer.MIN_VALUE) {
            throw new CommandLine.TypeConversionException(InputException.quote(text) + " is too large");
        }
        return (int) n;
    }

    /** An option's decimal number: ASCII digits, a point, an exponent; no hex, no NaN or Infinity. */
    static Double decimalNumber(String text) {
        if (!text.matches("[-+]?([0-9]{1,10}(\\.[0-9]{0,10})?|\\.[0-9]{1,10})([eE][-+]?[0-9]{1,3})?")) {
            throw new CommandLine.TypeConversionException(InputException.quote(text)
                    + " is not a number written with the digits 0-9 (as 1.5 or -2)");
        }
        return Double.parseDouble(text);
    }

    /** An option's file name; one the platform cannot take is refused in words. */
    static Path fileName(String text) {
        try {
            return FileNames.path(text);
        } catch (FileNames.InvalidNameException e) {
            throw new CommandLine.TypeConversionException(e.getMessage());
        }
    }

    @Override
    public Integer call() throws Exception {
        notEmpty("--scene", scene);
        notEmpty("--config", config);
        notEmpty("--output", output);
        for (String option : List.of("--scene", "--config", "--output")) {
            String problem = typed(option) == null ? null : FileNames.folderNameProblem(typed(option));
            if (problem != null) {
                throw new InputException("glint", 0, 0, option + ": " + problem);
            }
        }
        Config settings = overrides(loadConfig());
        Path scenePath = scene != null ? scene : sceneFromConfig(settings);
        if (output != null && bench != null) {
            throw new InputException("glint", 0, 0, "--output and --bench cannot be used together");
        }
        ViewChoice camera = ViewChoice.of(view);
        if (output != null) {
            List<Path> inputs = new ArrayList<>(List.of(scenePath));
            Path configFile = config != null ? config : Path.of("config.properties");
            if (Files.exists(configFile)) {
                inputs.add(configFile);
            }
            return Headless.renderStill(scenePath, camera, inputs, settings, flags(), output, out, err);
        }
        if (bench != null) {
            if (bench < 1 || bench > Headless.MAX_BENCH_FRAMES) {
                throw new InputException("glint", 0, 0, "--bench: expected a number of frames from 1 to "
                        + Headless.MAX_BENCH_FRAMES + ", got " + bench);
            }
            return Headless.bench(scenePath, camera, settings, flags(), bench, out, err);
        }
        if (view != null) {
            throw new InputException("glint", 0, 0, "--view renders headless: add --output FILE.png or --bench N "
                    + "(in the window, keys 1 to 9 go to the scene's views)");
        }
        Path configFile = config != null ? config : Files.exists(Path.of("config.properties"))
                ? Path.of("config.properties") : null;
        return WindowLauncher.open(scenePath, configFile, settings, flags(), () -> overrides(loadConfig()), out, err);
    }

    private Config loadConfig() throws InputException {
        if (config != null) {
            return ConfigLoader.load(config);
        }
        Path fallback = Path.of("config.properties");
        return Files.exists(fallback) ? ConfigLoader.load(fallback) : Config.defaults();
    }

    /** A file option's value as it was typed (the last one given), or null when it was not. */
    private String typed(String option) {
        var matched = spec.commandLine().getParseResult().matchedOption(option);
        if (matched == null || matched.originalStringValues().isEmpty()) {
            return null;
        }
        List<String> values = matched.originalStringValues();
        return values.get(values.size() - 1);
    }

    /** A path option given as an empty string would mean the current folder. */
    private static void notEmpty(String option, Path path) throws InputException {
        if (path != null && path.toString().isEmpty()) {
            throw new InputException("glint", 0, 0, option + ": expected a file name, got nothing");
        }
    }

    /**
     * The config's scene, relative to the folder of the config file. When that file does not exist,
     * the error is at the config's {@code scene} line (or its first line, for the default) and says
     * against which folder the path was resolved.
     */
    private Path sceneFromConfig(Config settings) throws InputException {
        Path configFile = config != null ? config : Files.exists(Path.of("config.properties"))
                ? Path.of("config.properties") : null;
        Path configured;
        try {
            configured = FileNames.path(settings.scene());
        } catch (FileNames.InvalidNameException e) {
            InputException at = configFile != null ? ConfigLoader.errorAt(configFile, "scene", "")
                    : new InputException("glint", 0, 0, "");
            throw new InputException(at.file(), at.line(), at.column(), "scene: " + e.getMessage());
        }
        Path resolved = configured.isAbsolute() || config == null || config.getParent() == null
                ? configured : config.getParent().resolve(configured);
        String folderName = FileNames.folderNameProblem(settings.scene().endsWith("/") ? resolved + "/" : "");
        if (folderName != null) {
            InputException at = configFile != null ? ConfigLoader.errorAt(configFile, "scene", "")
                    : new InputException("glint", 0, 0, "");
            throw new InputException(at.file(), at.line(), at.column(), "scene: " + folderName);
        }
        if (configFile == null && !Files.exists(resolved)) {
            throw new InputException("glint", 0, 0, "no such scene file " + InputException.quotePath(resolved)
                    + ": there is no ./config.properties in the current folder ("
                    + InputException.cutPath(Path.of("").toAbsolutePath().toString())
                    + "), so the default scene is looked up from there; name a scene with --scene FILE "
                    + "(or a config with --config FILE)");
        }
        if (configFile == null || Files.exists(resolved)) {
            return resolved;
        }
        Path folder = configFile.toAbsolutePath().getParent();
        InputException at = ConfigLoader.errorAt(configFile, "scene", "");
        String problem = (at.line() > 0 ? "scene: no such file " : "no such scene file ")
                + InputException.quotePath(resolved)
                + (configured.isAbsolute() ? "" : " (scene is resolved against the config file's folder, "
                        + InputException.cutPath(folder.toString()) + (at.line() > 0 ? ")" : "; the default is scenes/default.yaml)"))
                + "; set scene in the config or use --scene FILE";
        throw new InputException(at.file(), at.line(), at.column(), problem);
    }

    /** The command line's settings, which rank above the scene's render: block and the config. */
    private Flags flags() {
        return new Flags(width, height, spp, threads, depth, shading, integrator, exposure, tone, noise, maxSamples);
    }

    private Config overrides(Config c) throws InputException {
        return flags().apply(c);
    }
}
