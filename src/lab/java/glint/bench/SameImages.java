package glint.bench;

import glint.image.PfmReader;
import glint.study.RelativeMse;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * Whether two builds of Glint render the same images: each scene, by Whitted's integrator under both
 * shading models and by the path integrator, is
 * written as a PFM by each build (loaded in a class loader of its own, as {@link CompareBuilds}
 * does) and the two files compared: the same bytes, or else the relative mean square error of the
 * reference images' README.
 *
 * <p>Usage, from the repository root: {@code java -cp target/benchmarks.jar glint.bench.SameImages
 * A.jar B.jar [--size WxH] [--spp N] [--depth D] [--config FILE] [--tolerance E] SCENE...} (default
 * 320x240, 4 samples a pixel, depth 8, ./config.properties, tolerance 0). Prints a line a scene and
 * method; exits 1 when a pair's relative mean square error is above the tolerance.
 */
public final class SameImages {

    /** Each integrator with each shading model it takes: Whitted's with both, the path with cook-torrance. */
    private static final String[][] METHODS = {{"whitted", "cook-torrance"}, {"whitted", "phong"},
            {"path", "cook-torrance"}};

    private SameImages() {
    }

    public static void main(String[] args) throws Exception {
        List<String> rest = new ArrayList<>(Arrays.asList(args));
        String[] size = CompareBuilds.option(rest, "--size", "320x240").split("x");
        String spp = CompareBuilds.option(rest, "--spp", "4");
        String depth = CompareBuilds.option(rest, "--depth", "8");
        String config = CompareBuilds.option(rest, "--config", null);
        double tolerance = Double.parseDouble(CompareBuilds.option(rest, "--tolerance", "0"));
        if (rest.size() < 3) {
            System.err.println("usage: SameImages A.jar B.jar [--size WxH] [--spp N] [--depth D] [--config FILE]"
                    + " [--tolerance E] SCENE...");
            System.exit(2);
        }
        Method a = CompareBuilds.mainOf(Path.of(rest.get(0)));
        Method b = CompareBuilds.mainOf(Path.of(rest.get(1)));
        Path folder = Files.createTempDirectory("same-images");
        boolean allWithin = true;
        for (String scene : rest.subList(2, rest.size())) {
            for (String[] method : METHODS) {
                List<String> render = new ArrayList<>(List.of("--scene", scene, "--width", size[0], "--height",
                        size[1], "--spp", spp, "--depth", depth, "--integrator", method[0], "--shading", method[1]));
                if (config != null) {
                    render.addAll(List.of("--config", config));
                }
                Path imageA = write(a, render, folder.resolve("a.pfm"));
                Path imageB = write(b, render, folder.resolve("b.pfm"));
                double error = relativeMse(imageA, imageB);
                allWithin &= error <= tolerance;
                System.out.println(scene + ", " + method[0] + " " + method[1] + ": " + verdict(imageA, imageB, error));
            }
        }
        try (var files = Files.list(folder)) {
            for (Path file : files.toList()) {
                Files.delete(file);
            }
        }
        Files.delete(folder);
        System.exit(allWithin ? 0 : 1);
    }

    /** The relative mean square error of B against A: 0 for the same bytes. */
    static double relativeMse(Path imageA, Path imageB) throws Exception {
        if (Arrays.equals(Files.readAllBytes(imageA), Files.readAllBytes(imageB))) {
            return 0;
        }
        return RelativeMse.of(PfmReader.read(imageB), PfmReader.read(imageA));
    }

    /** "the same bytes", or the error and how many values differ. */
    private static String verdict(Path imageA, Path imageB, double error) throws Exception {
        if (Arrays.equals(Files.readAllBytes(imageA), Files.readAllBytes(imageB))) {
            return "the same bytes";
        }
        float[] x = PfmReader.read(imageA).rgb(), y = PfmReader.read(imageB).rgb();
        int differing = 0;
        for (int i = 0; i < x.length; i++) {
            differing += Float.compare(x[i], y[i]) != 0 ? 1 : 0;
        }
        return String.format(Locale.ROOT, "relative mean square error %.3g, %d of %d values differ", error,
                differing, x.length);
    }

    private static Path write(Method main, List<String> render, Path output) throws Exception {
        List<String> args = new ArrayList<>(render);
        args.addAll(List.of("--output", output.toString()));
        CompareBuilds.run(main, args.toArray(new String[0]));
        return output;
    }
}
