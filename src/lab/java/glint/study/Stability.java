package glint.study;

import glint.render.Tracer;
import java.io.IOException;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * The stability study: for each known failure of a textbook method, the textbook method beside
 * Glint's, charted into images/stability-*.png with the tables of stability.md in an output folder:
 * target/study/ by default, docs/ itself with --docs, or --out DIR. Run from the repository root, with the
 * lab jar built (docs/benchmarks.md; about half a minute on 2 cores):
 *
 * <pre>java -cp target/benchmarks.jar glint.study.Stability [--docs | --out DIR] [--only SECTION,...]</pre>
 *
 * With {@code --only}, just the named sections ({@link #SECTIONS}) are written.
 */
public final class Stability {

    static final String COMMAND = "java -cp target/benchmarks.jar glint.study.Stability";

    private Stability() {
    }

    /** The generated sections, by the name of their markers less "stability-", in the page's order. */
    static final List<String> SECTIONS = List.of("sphere", "offset", "fresnel", "microfacet", "quaternion",
            "ggx-sampling", "fireflies", "glass-sky", "cone", "sized-fireflies");

    static final String USAGE = "usage: Stability [--docs | --out DIR] [--only SECTION,...]";

    public static void main(String[] args) throws Exception {
        Path out;
        Set<String> only;
        try {
            out = output(args);
            only = only(args);
        } catch (IllegalArgumentException e) {
            System.err.println("Stability: " + e.getMessage());
            System.exit(2);
            return;
        }
        Path images = out.resolve("images");
        Path doc = out.resolve("stability.md");
        if (only.isEmpty()) {
            String command = COMMAND + (args.length > 0 ? " " + String.join(" ", args) : "");
            String stamp = "Generated " + LocalDate.now() + " by `" + command + "` (" + Runtime.getRuntime().availableProcessors()
                    + " cores, shared; the results do not depend on the machine: they are counts, not times).";
            GeneratedSection.write(doc, "stability-stamp", stamp);
        }
        try (Tracer tracer = new Tracer(Runtime.getRuntime().availableProcessors())) {
            for (String name : SECTIONS) {
                if (only.isEmpty() || only.contains(name)) {
                    GeneratedSection.write(doc, "stability-" + name, section(name, images, tracer));
                }
            }
        }
        System.out.println("wrote " + images.resolve("stability-*.png") + " and " + doc);
    }

    private static String section(String name, Path images, Tracer tracer) throws IOException {
        return switch (name) {
            case "sphere" -> spheres(images);
            case "offset" -> offsets(images);
            case "fresnel" -> fresnel(images);
            case "microfacet" -> microfacet(images);
            case "quaternion" -> quaternion(images);
            case "ggx-sampling" -> PathStability.ggx(images);
            case "fireflies" -> PathStability.fireflies(images, tracer);
            case "glass-sky" -> PathStability.glass(images, tracer);
            case "cone" -> LightStability.cone(images);
            case "sized-fireflies" -> LightStability.fireflies(images, tracer);
            default -> throw new IllegalArgumentException(name);
        };
    }

    /** The output folder the arguments choose: target/study, docs/ with --docs, or --out DIR. */
    static Path output(String... args) {
        Path out = Path.of("target/study");
        int choices = 0;
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("--out") && i + 1 < args.length) {
                out = Path.of(args[++i]);
            } else if (args[i].equals("--docs")) {
                out = Path.of("docs");
            } else if (args[i].equals("--only") && i + 1 < args.length) {
                i++;
                continue;
            } else {
                throw new IllegalArgumentException("unexpected '" + args[i] + "'; " + USAGE);
            }
            choices++;
        }
        if (choices > 1) {
            throw new IllegalArgumentException("--docs and --out both choose the output folder; give one");
        }
        return out;
    }

    /**
     * The sections {@code --only} names (empty: all, with the page's date stamp; a run of some sections
     * leaves the stamp and the others as they were).
     */
    static Set<String> only(String... args) {
        Set<String> names = new LinkedHashSet<>();
        for (int i = 0; i + 1 < args.length; i++) {
            if (args[i].equals("--only")) {
                for (String name : args[++i].split(",")) {
                    if (!SECTIONS.contains(name.strip())) {
                        throw new IllegalArgumentException("no section '" + name.strip() + "'; sections: "
                                + String.join(", ", SECTIONS));
                    }
                    names.add(name.strip());
                }
            } else if (args[i].equals("--out")) {
                i++;
            }
        }
        return names;
    }

    // ---- ray-sphere -----------------------------------------------------------------------------

    static final int SPHERE_PIXELS = 64;

    private static String spheres(Path images) throws IOException {
        StringBuilder md = new StringBuilder();
        double[] far = new double[32], huge = new double[33];
        for (int k = 1; k <= 32; k++) {
            far[k - 1] = Math.pow(10, k / 4.0);
        }
        for (int k = 0; k <= 32; k++) {
            huge[k] = Math.pow(10, k / 4.0);
        }
        Map<SphereMethod, SphereErrors[]> farErrors = sweep(far, true);
        Map<SphereMethod, SphereErrors[]> hugeErrors = sweep(huge, false);
        StabilityCharts.sphere("unit sphere far away", "distance to the centre, radii", far, farErrors,
                images.resolve("stability-sphere-far.png"));
        StabilityCharts.sphere("huge sphere, camera 1 above", "sphere radius", huge, hugeErrors,
                images.resolve("stability-sphere-huge.png"));
        md.append("Unit sphere at a distance D (").append(SPHERE_PIXELS).append(" x ").append(SPHERE_PIXELS)
                .append(" pixels, the disc spans 80 % of the width); wrong pixels, as hit/miss + distance:\n\n");
        md.append(sphereTable("D (radii)", far, farErrors));
        md.append("\nSphere of radius R, camera 1 unit above its top looking 15 degrees down (").append(SPHERE_PIXELS)
                .append(" x ").append(SPHERE_PIXELS).append(" pixels):\n\n");
        md.append(sphereTable("R", huge, hugeErrors));
        return md.toString();
    }

    private static Map<SphereMethod, SphereErrors[]> sweep(double[] values, boolean farSphere) {
        Map<SphereMethod, SphereErrors[]> result = new EnumMap<>(SphereMethod.class);
        for (SphereMethod m : SphereMethod.values()) {
            result.put(m, new SphereErrors[values.length]);
        }
        for (int i = 0; i < values.length; i++) {
            SphereView view = farSphere ? SphereView.farSphere(values[i], SPHERE_PIXELS)
                    : SphereView.hugeSphere(values[i], SPHERE_PIXELS);
            Map<SphereMethod, SphereErrors> r = SphereStudy.run(view);
            for (SphereMethod m : SphereMethod.values()) {
                result.get(m)[i] = r.get(m);
            }
        }
        return result;
    }

    /** Rows at whole decades only. */
    private static String sphereTable(String head, double[] x, Map<SphereMethod, SphereErrors[]> errors) {
        StringBuilder b = new StringBuilder("| ").append(head);
        for (SphereMethod m : SphereMethod.values()) {
            b.append(" | ").append(m.label());
        }
        b.append(" |\n|--:");
        b.append("|--:".repeat(SphereMethod.values().length)).append("|\n");
        for (int i = 0; i < x.length; i++) {
            double log = Math.log10(x[i]);
            if (Math.abs(log - Math.rint(log)) > 1e-9) {
                continue;
            }
            b.append("| 1e").append((int) Math.rint(log));
            for (SphereMethod m : SphereMethod.values()) {
                SphereErrors e = errors.get(m)[i];
                b.append(" | ").append(e.wrongHitMiss()).append(" + ").append(e.wrongDistance());
            }
            b.append(" |\n");
        }
        return b.toString();
    }

    // ---- self-intersection ----------------------------------------------------------------------

    static List<OffsetMethod> offsetMethods() {
        return List.of(new OffsetMethod.Fixed(Precision.FLOAT, 1e-4), new OffsetMethod.Fixed(Precision.DOUBLE, 1e-4),
                new OffsetMethod.Glint(1e-6), new OffsetMethod.Glint(1e-9), new OffsetMethod.Glint(1e-12));
    }

    private static String offsets(Path images) throws IOException {
        List<OffsetMethod> methods = offsetMethods();
        double[] moves = new double[14];
        for (int k = 0; k < moves.length; k++) {
            moves[k] = Math.pow(10, k);
        }
        double[] radii = new double[10];
        for (int k = 0; k < radii.length; k++) {
            radii[k] = Math.pow(10, k);
        }
        OffsetErrors[][] contact = new OffsetErrors[methods.size()][moves.length];
        OffsetErrors[][] ground = new OffsetErrors[methods.size()][radii.length];
        ShadowScene scene = ShadowScene.contact(160, 120);
        ShadowTruth truth = ShadowTruth.of(scene);
        try (Tracer tracer = new Tracer(Runtime.getRuntime().availableProcessors())) {
            for (int m = 0; m < methods.size(); m++) {
                for (int i = 0; i < moves.length; i++) {
                    contact[m][i] = OffsetStudy.moved(scene, truth, moves[i], methods.get(m), tracer);
                }
                for (int i = 0; i < radii.length; i++) {
                    ground[m][i] = OffsetStudy.moved(ShadowScene.groundSphere(radii[i], 160, 120), 0, methods.get(m),
                            tracer);
                }
            }
        }
        StabilityCharts.offsets(moves, radii, methods, contact, ground, images.resolve("stability-offset.png"));
        StringBuilder md = new StringBuilder();
        md.append(String.format(Locale.ROOT, "Contact scene, 160 x 120 pixels: %d lit, %d in a cast shadow, %d excluded "
                        + "as ambiguous. Each cell: acne / missed shadow / shadowed by the offset itself, in pixels.%n%n",
                truth.count(ShadowTruth.LIT), truth.count(ShadowTruth.SHADOW), truth.count(ShadowTruth.EXCLUDED)));
        md.append("| s");
        for (OffsetMethod m : methods) {
            md.append(" | ").append(m.label().replace("|", "\\|"));
        }
        md.append(" |\n|--:").append("|--:".repeat(methods.size())).append("|\n");
        for (int i = 0; i < moves.length; i++) {
            md.append("| 1e").append(i);
            for (int m = 0; m < methods.size(); m++) {
                OffsetErrors e = contact[m][i];
                md.append(" | ").append(e.acne()).append(" / ").append(e.missedShadow()).append(" / ").append(e.overshoot());
            }
            md.append(" |\n");
        }
        md.append("\nGround sphere of radius R with its top at the origin (160 x 120 pixels, all ground pixels lit): "
                + "acne pixels.\n\n| R");
        for (OffsetMethod m : methods) {
            md.append(" | ").append(m.label().replace("|", "\\|"));
        }
        md.append(" |\n|--:").append("|--:".repeat(methods.size())).append("|\n");
        for (int i = 0; i < radii.length; i++) {
            md.append("| 1e").append(i);
            for (int m = 0; m < methods.size(); m++) {
                md.append(" | ").append(ground[m][i].acne()).append(" of ").append(ground[m][i].litPixels());
            }
            md.append(" |\n");
        }
        return md.toString();
    }

    // ---- Fresnel --------------------------------------------------------------------------------

    private static String fresnel(Path images) throws IOException {
        double[] angles = FresnelCurves.angles(0.25);
        StabilityCharts.fresnel(angles, images.resolve("stability-fresnel.png"));
        double[] fine = FresnelCurves.angles(0.01);
        double outside = 0, outsideAt = 0, inside = 0, insideAt = 0, slip = 0, slipAt = 0;
        for (double a : fine) {
            double eo = Math.abs(FresnelCurves.schlickOutside(a) - FresnelCurves.exactOutside(a));
            double ei = Math.abs(FresnelCurves.schlickInside(a) - FresnelCurves.exactInside(a));
            double ew = Math.abs(FresnelCurves.schlickWrongCosineInside(a) - FresnelCurves.exactInside(a));
            if (eo > outside) {
                outside = eo;
                outsideAt = a;
            }
            if (ei > inside) {
                inside = ei;
                insideAt = a;
            }
            if (ew > slip) {
                slip = ew;
                slipAt = a;
            }
        }
        return String.format(Locale.ROOT, """
                Largest |Schlick - exact| over 0..90 degrees in steps of 0.01 degree (ior 1.5, F0 = %.4f):

                | case | largest error | at |
                |---|--:|--:|
                | from outside | %.4f | %.2f deg |
                | from inside, Schlick with the air-side cosine and TIR (Glint's `SCHLICK` option) | %.4f | %.2f deg |
                | from inside, Schlick with the incident cosine (textbook slip) | %.4f | %.2f deg |
                """, FresnelCurves.f0(), outside, outsideAt, inside, insideAt, slip, slipAt);
    }

    // ---- Cook-Torrance --------------------------------------------------------------------------

    static final double[] LOBE_ANGLES = {0, 30, 60, 85, 89, 89.999, 90};
    static final double[] LOBE_ROUGHNESS = {0, 1e-300, 1e-160, 1e-8, 1e-6, 1e-3, 0.1, 0.5, 1};

    private static String microfacet(Path images) throws IOException {
        double[] roughness = {1e-6, 0.1, 0.25, 0.5, 1};
        double[] view = new double[90];
        for (int i = 0; i < view.length; i++) {
            view[i] = Math.min(89.9, i + 0.0);
        }
        view[view.length - 1] = 89.9;
        double[][] glint = new double[roughness.length][view.length];
        double[][] textbook = new double[roughness.length][view.length];
        for (int r = 0; r < roughness.length; r++) {
            for (int i = 0; i < view.length; i++) {
                double cosView = Math.cos(Math.toRadians(view[i]));
                glint[r][i] = Microfacet.glintAlbedo(cosView, roughness[r], 256);
                textbook[r][i] = Microfacet.textbookAlbedo(cosView, roughness[r], 256);
            }
        }
        StabilityCharts.microfacet(view, roughness, glint, textbook, images.resolve("stability-cook-torrance.png"));
        StringBuilder md = new StringBuilder();
        md.append("Values that are not finite numbers, of each lobe evaluated at every pairing of view and light at ")
                .append("0, 30, 60, 85, 89, 89.999 and 90 degrees from the normal, azimuths 0, 90 and 180 degrees apart:\n\n");
        md.append("| roughness | Glint | textbook | evaluations |\n|--:|--:|--:|--:|\n");
        for (double r : LOBE_ROUGHNESS) {
            int[] bad = Microfacet.nonFinite(LOBE_ANGLES, r);
            md.append("| ").append(Numbers.sci(r)).append(" | ").append(bad[0]).append(" | ").append(bad[1])
                    .append(" | ").append(bad[2]).append(" |\n");
        }
        md.append("\nDirectional albedo (Fresnel = 1), largest over view angles 0..89.9 degrees:\n\n");
        md.append("| roughness | Glint | textbook |\n|--:|--:|--:|\n");
        for (int r = 0; r < roughness.length; r++) {
            md.append("| ").append(Numbers.sci(roughness[r])).append(" | ")
                    .append(Numbers.fixed(max(glint[r]), 4)).append(" | ").append(Numbers.fixed(max(textbook[r]), 4))
                    .append(" |\n");
        }
        return md.toString();
    }

    private static double max(double[] v) {
        double m = Double.NEGATIVE_INFINITY;
        for (double x : v) {
            m = Math.max(m, x);
        }
        return m;
    }

    // ---- quaternion -----------------------------------------------------------------------------

    private static String quaternion(Path images) throws IOException {
        long[] turns = QuaternionDrift.checkpoints(1_000_000);
        Map<String, double[]> errors = new LinkedHashMap<>();
        errors.put("double, never re-normalised", QuaternionDrift.normError(turns, Precision.DOUBLE, false));
        errors.put("double, re-normalised every turn", QuaternionDrift.normError(turns, Precision.DOUBLE, true));
        errors.put("float, never re-normalised", QuaternionDrift.normError(turns, Precision.FLOAT, false));
        errors.put("float, re-normalised every turn", QuaternionDrift.normError(turns, Precision.FLOAT, true));
        StabilityCharts.quaternion(turns, errors, images.resolve("stability-quaternion.png"));
        StringBuilder md = new StringBuilder("| turns");
        for (String k : errors.keySet()) {
            md.append(" | ").append(k);
        }
        md.append(" |\n|--:").append("|--:".repeat(errors.size())).append("|\n");
        List<Integer> rows = new ArrayList<>();
        for (int i = 0; i < turns.length; i++) {
            if (turns[i] >= 1000 && Long.toString(turns[i]).startsWith("1")) {
                rows.add(i);
            }
        }
        for (int i : rows) {
            md.append("| ").append(String.format(Locale.ROOT, "%,d", turns[i]));
            for (double[] e : errors.values()) {
                md.append(" | ").append(String.format(Locale.ROOT, "%.1e", e[i]));
            }
            md.append(" |\n");
        }
        return md.toString();
    }
}
