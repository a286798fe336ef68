package glint.config;

import glint.image.ViewTransform;
import glint.input.InputException;
import glint.render.LightTransport;
import glint.render.RenderSettings;
import glint.render.Shading;
import java.util.function.Consumer;

/**
 * The settings of config.properties (docs/config.md), each with a default.
 *
 * @param debug          print diagnostics (timings, tile counts) to standard error
 * @param epsilon        base of the self-intersection offset: a spawned ray starts
 *                       epsilon x max(1, |p|) off the surface
 * @param displayScale   the window renders at 1/scale of its size (the floor while moving)
 * @param screenDivider  the frame is split into divider x divider tiles
 * @param displayWidth   window and default image width in pixels
 * @param displayHeight  window and default image height in pixels
 * @param recursionMax   surface hits along a path (1 = direct light only)
 * @param name           the window title
 * @param scene          the scene file, relative to the config file's folder
 * @param threads        render threads, 0 = one per core
 * @param shading        shading model
 * @param samples        samples per pixel, a perfect square
 * @param minWeight      rays whose weight (largest channel of the path throughput) falls below this
 *                       are not traced
 * @param moveSpeed      camera speed in scene units per second
 * @param turnSpeed      camera turn rate in degrees per second
 * @param targetFps      the frame rate the window holds while the camera moves
 * @param limits         safety limits on image size, scene size and recursion
 * @param freeFlight     window: the camera turns about its own axes, pitch unbounded, instead of
 *                       keeping the horizon level
 * @param transport      the integrator: Whitted or path tracing (key {@code integrator})
 * @param view           the view transform of the 8-bit images: exposure and tone curve (keys {@code exposure},
 *                       {@code tone})
 * @param noise          adaptive sampling's threshold, the relative noise a pixel of the path and bdpt integrators
 *                       stops at: a still is rendered to it (instead of {@code samples} a pixel) when above 0, and
 *                       the window refines to it at rest (to {@link glint.render.Convergence#WINDOW_NOISE} when 0)
 * @param maxSamples     the most samples a pixel gets where adaptive sampling decides (key {@code max_samples})
 * @param sizeSetAt      where a config file set the image size (or lowered the limit the default size breaks),
 *                       for a refusal of a size beyond the limit; null when none did, or once the size was set
 *                       elsewhere (a scene's render: block, --width), which is checked there
 */
public record Config(boolean debug, double epsilon, double displayScale, int screenDivider,
                     int displayWidth, int displayHeight, int recursionMax, String name,
                     String scene, int threads, Shading shading, int samples, double minWeight,
                     double moveSpeed, double turnSpeed, double targetFps, Limits limits,
                     boolean freeFlight, LightTransport transport, ViewTransform view, double noise,
                     int maxSamples, Place sizeSetAt) {

    /**
     * The default cap of adaptive sampling: 1024 samples a pixel, the most the speed/accuracy study renders
     * (docs/accuracy.md), where the reference scenes are within FLIP 0.02 of their converged images.
     */
    public static final int MAX_SAMPLES = 1024;

    /** A line and column of a config file. */
    public record Place(String file, int line, int column) {
    }

    /** A config without adaptive stills, capped at {@link #MAX_SAMPLES}, whose size no config file set. */
    public Config(boolean debug, double epsilon, double displayScale, int screenDivider,
                  int displayWidth, int displayHeight, int recursionMax, String name,
                  String scene, int threads, Shading shading, int samples, double minWeight,
                  double moveSpeed, double turnSpeed, double targetFps, Limits limits, boolean freeFlight,
                  LightTransport transport, ViewTransform view) {
        this(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight, recursionMax, name, scene,
                threads, shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits, freeFlight,
                transport, view, 0, MAX_SAMPLES, null);
    }

    /** A config of the default view transform. */
    public Config(boolean debug, double epsilon, double displayScale, int screenDivider,
                  int displayWidth, int displayHeight, int recursionMax, String name,
                  String scene, int threads, Shading shading, int samples, double minWeight,
                  double moveSpeed, double turnSpeed, double targetFps, Limits limits, boolean freeFlight,
                  LightTransport transport) {
        this(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight, recursionMax, name, scene,
                threads, shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits, freeFlight,
                transport, ViewTransform.DEFAULT);
    }

    /** A config of the Whitted integrator. */
    public Config(boolean debug, double epsilon, double displayScale, int screenDivider,
                  int displayWidth, int displayHeight, int recursionMax, String name,
                  String scene, int threads, Shading shading, int samples, double minWeight,
                  double moveSpeed, double turnSpeed, double targetFps, Limits limits, boolean freeFlight) {
        this(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight, recursionMax, name, scene,
                threads, shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits, freeFlight,
                LightTransport.WHITTED);
    }

    /** A config with a level camera (free_flight=false). */
    public Config(boolean debug, double epsilon, double displayScale, int screenDivider,
                  int displayWidth, int displayHeight, int recursionMax, String name,
                  String scene, int threads, Shading shading, int samples, double minWeight,
                  double moveSpeed, double turnSpeed, double targetFps, Limits limits) {
        this(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight, recursionMax, name, scene,
                threads, shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits, false);
    }

    public static Config defaults() {
        return new Config(false, 1e-9, 2, 8, 800, 600, 16, "Glint", "scenes/default.yaml",
                0, Shading.COOK_TORRANCE, 4, 1e-2, 2.0, 60, 30, Limits.DEFAULT);
    }

    /** What the renderer reads of this config: the shading model, depth, pruning, offset and integrator. */
    public RenderSettings renderSettings() {
        return new RenderSettings(shading, recursionMax, minWeight, epsilon).withTransport(transport);
    }

    /** Threads actually used: {@code threads}, or one per available core when it is 0. */
    public int effectiveThreads() {
        return threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }

    /** This config at another size, set elsewhere than a config file (checked where it is set). */
    public Config withSize(int width, int height) {
        return with(c -> {
            c.displayWidth = width;
            c.displayHeight = height;
            c.sizeSetAt = null;
        });
    }

    /** This config with its size set at {@code place} of a config file. */
    public Config withSizeSetAt(Place place) {
        return with(c -> c.sizeSetAt = place);
    }

    /**
     * Why this config's image size is beyond its limit ({@code max_image_pixels}), positioned where a config
     * file set it; null when it is within. Asked of the settings a scene is rendered with, after the render:
     * block and the flags, which may set another size.
     */
    public InputException sizeRefusal() {
        String problem = limits.imageSizeProblem(displayWidth, displayHeight);
        if (problem == null) {
            return null;
        }
        Place at = sizeSetAt != null ? sizeSetAt : new Place("glint", 0, 0);
        return new InputException(at.file(), at.line(), at.column(), "display_width x display_height: " + problem);
    }

    public Config withSamples(int newSamples) {
        return with(c -> c.samples = newSamples);
    }

    public Config withThreads(int newThreads) {
        return with(c -> c.threads = newThreads);
    }

    public Config withRecursionMax(int depth) {
        return with(c -> c.recursionMax = depth);
    }

    public Config withShading(Shading model) {
        return with(c -> c.shading = model);
    }

    public Config withTransport(LightTransport integrator) {
        return with(c -> c.transport = integrator);
    }

    public Config withView(ViewTransform transform) {
        return with(c -> c.view = transform);
    }

    public Config withNoise(double threshold) {
        return with(c -> c.noise = threshold);
    }

    public Config withMaxSamples(int cap) {
        return with(c -> c.maxSamples = cap);
    }

    /** Whether a still is rendered by adaptive sampling: a path or bdpt still with a noise threshold. */
    public boolean adaptiveStill() {
        return transport.physical() && noise > 0;
    }

    /** The threshold the window refines to at rest: {@code noise}, or the window's own where it is 0. */
    public double windowNoise() {
        return noise > 0 ? noise : glint.render.Convergence.WINDOW_NOISE;
    }

    public Config withScreenDivider(int divider) {
        return with(c -> c.screenDivider = divider);
    }

    public Config withMinWeight(double weight) {
        return with(c -> c.minWeight = weight);
    }

    public Config withScene(String sceneFile) {
        return with(c -> c.scene = sceneFile);
    }

    public Config withLimits(Limits newLimits) {
        return with(c -> c.limits = newLimits);
    }

    public Config withFreeFlight(boolean free) {
        return with(c -> c.freeFlight = free);
    }

    /** This config with the fields {@code change} sets, the others as they are. */
    private Config with(Consumer<Copy> change) {
        Copy copy = new Copy(this);
        change.accept(copy);
        return copy.build();
    }

    /** A config's fields to change a few of: read from one config, made into another by {@link #build}. */
    private static final class Copy {
        boolean debug;
        double epsilon;
        double displayScale;
        int screenDivider;
        int displayWidth;
        int displayHeight;
        int recursionMax;
        String name;
        String scene;
        int threads;
        Shading shading;
        int samples;
        double minWeight;
        double moveSpeed;
        double turnSpeed;
        double targetFps;
        Limits limits;
        boolean freeFlight;
        LightTransport transport;
        ViewTransform view;
        double noise;
        int maxSamples;
        Place sizeSetAt;

        Copy(Config c) {
            debug = c.debug;
            epsilon = c.epsilon;
            displayScale = c.displayScale;
            screenDivider = c.screenDivider;
            displayWidth = c.displayWidth;
            displayHeight = c.displayHeight;
            recursionMax = c.recursionMax;
            name = c.name;
            scene = c.scene;
            threads = c.threads;
            shading = c.shading;
            samples = c.samples;
            minWeight = c.minWeight;
            moveSpeed = c.moveSpeed;
            turnSpeed = c.turnSpeed;
            targetFps = c.targetFps;
            limits = c.limits;
            freeFlight = c.freeFlight;
            transport = c.transport;
            view = c.view;
            noise = c.noise;
            maxSamples = c.maxSamples;
            sizeSetAt = c.sizeSetAt;
        }

        Config build() {
            return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight, recursionMax,
                    name, scene, threads, shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits,
                    freeFlight, transport, view, noise, maxSamples, sizeSetAt);
        }
    }

    /** True when n is 1, 4, 9, 16, ... */
    public static boolean isPerfectSquare(int n) {
        if (n < 1) {
            return false;
        }
        int root = (int) Math.round(Math.sqrt(n));
        return root * root == n;
    }
}
