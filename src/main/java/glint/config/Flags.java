package glint.config;

import glint.image.ViewTransform;
import glint.input.InputException;
import glint.input.Suggestions;
import glint.render.LightTransport;
import glint.render.Shading;
import glint.scene.RenderBlock;
import java.util.List;
import java.util.function.Consumer;

/**
 * The command line's settings (--width, --height, --spp, --threads, --depth, --shading, --integrator, --exposure,
 * --tone); each is null when not given. They rank first: a flag beats the scene's {@code render:} block, which beats
 * config.properties, which beats the defaults ({@link #effective}).
 */
public record Flags(Integer width, Integer height, Integer samples, Integer threads, Integer depth, String shading,
                    String integrator, Double exposure, String tone, Double noise, Integer maxSamples) {

    /** Flags that leave adaptive sampling as it is. */
    public Flags(Integer width, Integer height, Integer samples, Integer threads, Integer depth, String shading,
                 String integrator, Double exposure, String tone) {
        this(width, height, samples, threads, depth, shading, integrator, exposure, tone, null, null);
    }

    /** No flag given. */
    public static final Flags NONE = new Flags(null, null, null, null, null, null, null);

    /** Flags that leave the view transform as it is. */
    public Flags(Integer width, Integer height, Integer samples, Integer threads, Integer depth, String shading,
                 String integrator) {
        this(width, height, samples, threads, depth, shading, integrator, null, null);
    }

    /** Why the path and bdpt integrators and the phong model do not go together. */
    public static final String PATH_NEEDS_COOK_TORRANCE = "the path and bdpt integrators need shading cook-torrance:"
            + " phong's coefficients are not a BSDF a path can sample (use --integrator whitted with phong)";

    /** Flags without an integrator. */
    public Flags(Integer width, Integer height, Integer samples, Integer threads, Integer depth, String shading) {
        this(width, height, samples, threads, depth, shading, null);
    }

    /** Whether a flag sets the image size. */
    public boolean setsSize() {
        return width != null || height != null;
    }

    /**
     * The settings a scene is rendered with: the defaults, under config.properties, under the scene's
     * {@code render:} block, under these flags; each checked against the config's limits where it is set, so a
     * refusal names the setting that broke a limit. Of two settings that cannot go together (the path
     * integrator and phong), the higher-ranked one wins and the other yields, with a note; two of the same rank
     * are an error.
     *
     * @throws InputException a flag or a key of the block is out of the config's limits, or two of the same
     *                        rank conflict
     */
    public Config effective(Config config, RenderBlock render) throws InputException {
        return effective(config, render, note -> { });
    }

    /** {@link #effective(Config, RenderBlock)}, each note of a setting that yielded told to {@code notes}. */
    public Config effective(Config config, RenderBlock render, Consumer<String> notes) throws InputException {
        Config result = apply(withBlock(config, render, this));
        InputException tooLarge = result.sizeRefusal(); // the config's own size, which neither the block nor a flag set
        if (tooLarge != null) {
            throw tooLarge;
        }
        Rank integratorRank = integrator != null ? Rank.FLAG : render.integrator() != null ? Rank.BLOCK : Rank.CONFIG;
        Rank shadingRank = shading != null ? Rank.FLAG : render.shading() != null ? Rank.BLOCK : Rank.CONFIG;
        if (!result.transport().physical() || result.shading() != Shading.PHONG) {
            return result;
        }
        String physical = "integrator " + result.transport().key();
        if (integratorRank == shadingRank) {
            throw sameRankConflict(render, integratorRank, result.transport());
        }
        boolean shadingYields = shadingRank.compareTo(integratorRank) < 0;
        notes.accept(shadingYields
                ? yieldNote(render, shadingRank, "shading", "shading phong", integratorRank, physical,
                        "rendering with cook-torrance")
                : yieldNote(render, integratorRank, "integrator", physical, shadingRank, "shading phong",
                        "rendering with whitted"));
        return shadingYields ? result.withShading(Shading.COOK_TORRANCE) : result.withTransport(LightTransport.WHITTED);
    }

    /** The integrator of the two settings that conflict, "integrator path" or "integrator bdpt", as its key. */
    private static String winnerOrYielding(String winner, String yielding) {
        String integrator = winner.startsWith("integrator ") ? winner : yielding;
        return integrator.substring("integrator ".length());
    }

    /** Who set a value, lowest first: the config (or the default), the scene's render: block, a flag. */
    private enum Rank {
        CONFIG, BLOCK, FLAG
    }

    private InputException sameRankConflict(RenderBlock render, Rank rank, LightTransport transport) {
        return switch (rank) {
            case FLAG -> new InputException("glint", 0, 0, "--integrator " + transport.key() + ": "
                    + PATH_NEEDS_COOK_TORRANCE);
            case BLOCK -> blockError(render, "integrator", "render: " + PATH_NEEDS_COOK_TORRANCE);
            case CONFIG -> new InputException("glint", 0, 0, "the config: " + PATH_NEEDS_COOK_TORRANCE);
        };
    }

    /** The note of a setting that yields to a higher-ranked one, at the place of the one that yields. */
    private static String yieldNote(RenderBlock render, Rank yieldingRank, String key, String yielding, Rank winnerRank,
                                    String winner, String outcome) {
        String what = name(yieldingRank, yielding) + " yields to " + name(winnerRank, winner)
                + " (the " + winnerOrYielding(winner, yielding) + " integrator needs cook-torrance); " + outcome;
        if (yieldingRank == Rank.BLOCK) {
            RenderBlock.Place at = render.place(key);
            return new InputException(render.file(), at.line(), at.column(), "note: " + what).getMessage();
        }
        return "glint: note: " + what;
    }

    private static String name(Rank rank, String setting) {
        return switch (rank) {
            case FLAG -> "--" + setting;
            case BLOCK -> "render: " + setting;
            case CONFIG -> "the config's " + setting;
        };
    }

    /**
     * The config with the block's keys put in, each checked against the config's limits unless a flag sets
     * the same value (then the flag's is the one checked).
     */
    static Config withBlock(Config c, RenderBlock r) throws InputException {
        return withBlock(c, r, NONE);
    }

    private static Config withBlock(Config c, RenderBlock r, Flags flags) throws InputException {
        if (r.shading() != null) {
            c = c.withShading(Shading.byKey(r.shading()));
        }
        if (r.integrator() != null) {
            c = c.withTransport(LightTransport.byKey(r.integrator()));
        }
        if (r.samples() != null) {
            c = c.withSamples(r.samples());
        }
        if (r.recursionMax() != null && flags.depth() == null) {
            int max = c.limits().maxRecursion();
            if (r.recursionMax() > max) {
                throw blockError(r, "recursion_max", "recursion_max in render must be at most " + max
                        + " (config key max_recursion), got " + r.recursionMax());
            }
            c = c.withRecursionMax(r.recursionMax());
        }
        if (r.noise() != null) {
            c = c.withNoise(r.noise());
        }
        if (r.maxSamples() != null) {
            c = c.withMaxSamples(r.maxSamples());
        }
        if (r.minWeight() != null) {
            c = c.withMinWeight(r.minWeight());
        }
        if (r.exposure() != null) {
            c = c.withView(c.view().withExposure(r.exposure()));
        }
        if (r.tone() != null) {
            c = c.withView(c.view().withTone(ViewTransform.Tone.byKey(r.tone())));
        }
        if (r.width() != null) {
            String tooLarge = flags.setsSize() ? null : c.limits().imageSizeProblem(r.width(), r.height());
            if (tooLarge != null) {
                throw blockError(r, "width", "width x height in render: " + tooLarge);
            }
            c = c.withSize(r.width(), r.height());
        }
        return c;
    }

    private static InputException blockError(RenderBlock r, String key, String problem) {
        RenderBlock.Place at = r.place(key);
        return new InputException(r.file(), at.line(), at.column(), problem);
    }

    /**
     * The config with these flags put in; a value out of range or beyond the config's limits is an error naming
     * the flag. Two settings that cannot go together are sorted out by {@link #effective}.
     */
    public Config apply(Config c) throws InputException {
        if (width != null || height != null) {
            int w = width != null ? width : c.displayWidth();
            int h = height != null ? height : c.displayHeight();
            checkRange("--width", w, 1, 65536);
            checkRange("--height", h, 1, 65536);
            String sizeProblem = c.limits().imageSizeProblem(w, h);
            if (sizeProblem != null) {
                throw new InputException("glint", 0, 0, "--width x --height: " + sizeProblem);
            }
            c = c.withSize(w, h);
        }
        if (samples != null) {
            if (!Config.isPerfectSquare(samples) || samples > 4096) {
                throw new InputException("glint", 0, 0,
                        "--spp: expected a perfect square from 1 to 4096 (1, 4, 9, 16, ...), got " + samples);
            }
            c = c.withSamples(samples);
        }
        if (noise != null) {
            if (!ConfigLoader.noiseInRange(noise)) {
                throw new InputException("glint", 0, 0, "--noise: expected " + ConfigLoader.NOISE_RANGE + ", got "
                        + plain(noise));
            }
            c = c.withNoise(noise);
        }
        if (maxSamples != null) {
            checkRange("--max-samples", maxSamples, 1, ConfigLoader.MAX_SAMPLES);
            c = c.withMaxSamples(maxSamples);
        }
        if (threads != null) {
            checkRange("--threads", threads, 0, 1024);
            c = c.withThreads(threads);
        }
        if (depth != null) {
            checkRange("--depth", depth, 1, c.limits().maxRecursion());
            c = c.withRecursionMax(depth);
        }
        if (shading != null) {
            Shading model = Shading.byKey(shading);
            if (model == null) {
                throw new InputException("glint", 0, 0, "--shading: unknown model " + InputException.quote(shading)
                        + Suggestions.hint(shading, List.of("cook-torrance", "phong")));
            }
            c = c.withShading(model);
        }
        if (integrator != null) {
            LightTransport transport = LightTransport.byKey(integrator);
            if (transport == null) {
                throw new InputException("glint", 0, 0, "--integrator: unknown integrator "
                        + InputException.quote(integrator) + ", expected " + LightTransport.IN_WORDS
                        + Suggestions.hint(integrator, LightTransport.KEYS));
            }
            c = c.withTransport(transport);
        }
        if (exposure != null) {
            if (!(Math.abs(exposure) <= ViewTransform.MAX_EXPOSURE)) {
                throw new InputException("glint", 0, 0, "--exposure: expected a number of stops from -16 to 16, got "
                        + ViewTransform.stops(exposure));
            }
            c = c.withView(c.view().withExposure(exposure));
        }
        if (tone != null) {
            ViewTransform.Tone curve = ViewTransform.Tone.byKey(tone);
            if (curve == null) {
                throw new InputException("glint", 0, 0, "--tone: unknown tone curve " + InputException.quote(tone)
                        + Suggestions.hint(tone, ViewTransform.Tone.KEYS));
            }
            c = c.withView(c.view().withTone(curve));
        }
        return c;
    }

    /** A number as a user writes it: {@code 0.00001}, {@code 2}, {@code -0.5}. */
    private static String plain(double x) {
        return Double.isFinite(x) ? new java.math.BigDecimal(Double.toString(x)).stripTrailingZeros().toPlainString()
                : Double.toString(x);
    }

    private static void checkRange(String option, int value, int min, int max) throws InputException {
        if (value < min || value > max) {
            throw new InputException("glint", 0, 0,
                    option + ": expected a whole number from " + min + " to " + max + ", got " + value);
        }
    }
}
