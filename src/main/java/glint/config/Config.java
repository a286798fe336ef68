package glint.config;

/**
 * The settings of config.properties (SPEC section 5), each with a default.
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
 */
public record Config(boolean debug, double epsilon, double displayScale, int screenDivider,
                     int displayWidth, int displayHeight, int recursionMax, String name,
                     String scene, int threads, Shading shading, int samples, double minWeight,
                     double moveSpeed, double turnSpeed, double targetFps, Limits limits,
                     boolean freeFlight) {

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

    /** Threads actually used: {@code threads}, or one per available core when it is 0. */
    public int effectiveThreads() {
        return threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }

    public Config withSize(int width, int height) {
        return new Config(debug, epsilon, displayScale, screenDivider, width, height, recursionMax, name,
                scene, threads, shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits, freeFlight);
    }

    public Config withSamples(int newSamples) {
        return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight,
                recursionMax, name, scene, threads, shading, newSamples, minWeight, moveSpeed, turnSpeed,
                targetFps, limits, freeFlight);
    }

    public Config withThreads(int newThreads) {
        return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight,
                recursionMax, name, scene, newThreads, shading, samples, minWeight, moveSpeed, turnSpeed,
                targetFps, limits, freeFlight);
    }

    public Config withRecursionMax(int depth) {
        return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight,
                depth, name, scene, threads, shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits,
                freeFlight);
    }

    public Config withShading(Shading model) {
        return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight,
                recursionMax, name, scene, threads, model, samples, minWeight, moveSpeed, turnSpeed,
                targetFps, limits, freeFlight);
    }

    public Config withScreenDivider(int divider) {
        return new Config(debug, epsilon, displayScale, divider, displayWidth, displayHeight,
                recursionMax, name, scene, threads, shading, samples, minWeight, moveSpeed, turnSpeed,
                targetFps, limits, freeFlight);
    }

    public Config withMinWeight(double weight) {
        return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight,
                recursionMax, name, scene, threads, shading, samples, weight, moveSpeed, turnSpeed,
                targetFps, limits, freeFlight);
    }

    public Config withScene(String sceneFile) {
        return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight,
                recursionMax, name, sceneFile, threads, shading, samples, minWeight, moveSpeed, turnSpeed,
                targetFps, limits, freeFlight);
    }

    public Config withLimits(Limits newLimits) {
        return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight,
                recursionMax, name, scene, threads, shading, samples, minWeight, moveSpeed, turnSpeed,
                targetFps, newLimits, freeFlight);
    }

    public Config withFreeFlight(boolean free) {
        return new Config(debug, epsilon, displayScale, screenDivider, displayWidth, displayHeight,
                recursionMax, name, scene, threads, shading, samples, minWeight, moveSpeed, turnSpeed,
                targetFps, limits, free);
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
