package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Scenes of legal values whose light is more than a float (3.4e38) or a double (1.8e308) holds,
 * rendered as a user renders them (the command line writing a PFM), in both shading models of the
 * Whitted integrator and in the path integrator: every float written is finite, and a pixel brighter
 * than a float is the largest float, never infinity, NaN or a black one.
 */
class FiniteImageTest {

    private static final float LARGEST = Float.MAX_VALUE;

    @TempDir
    Path dir;

    /** The models rendered: the Whitted integrator's two, and the path integrator (cook-torrance's BSDFs). */
    private static final String PATH = "path";

    /**
     * The PFM's floats, rows bottom to top as the file has them, after checking every one is finite:
     * {@code model} is a shading model of the Whitted integrator, or {@link #PATH}.
     */
    private float[] render(String sceneText, String model, int width, int height) throws IOException {
        boolean path = model.equals(PATH);
        String shading = path ? "cook-torrance" : model;
        Path scene = Files.writeString(dir.resolve("scene.yaml"), sceneText);
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        Path pfm = dir.resolve("out.pfm");
        StringWriter out = new StringWriter(), err = new StringWriter();
        int status = Main.run(new String[] {"--config", config.toString(), "--scene", scene.toString(), "--shading",
            shading, "--integrator", path ? "path" : "whitted", "--width", "" + width, "--height", "" + height,
            "--spp", "1", "--depth", "64", "--threads", "2", "--output", pfm.toString()},
                new PrintWriter(out, true), new PrintWriter(err, true));
        assertEquals(0, status, err.toString());
        byte[] bytes = Files.readAllBytes(pfm);
        String header = "PF\n" + width + " " + height + "\n-1.0\n";
        assertEquals(header, new String(bytes, 0, header.length(), StandardCharsets.US_ASCII));
        ByteBuffer body = ByteBuffer.wrap(bytes, header.length(), bytes.length - header.length())
                .order(ByteOrder.LITTLE_ENDIAN);
        float[] values = new float[3 * width * height];
        for (int i = 0; i < values.length; i++) {
            values[i] = body.getFloat();
            float v = values[i];
            assertTrue(Float.isFinite(v) && v >= 0, () -> "float " + v + " in " + model);
        }
        return values;
    }

    /** The three channels of pixel (x, y) of the image (y from the top), from the PFM's bottom-up rows. */
    private static float[] pixel(float[] pfm, int width, int height, int x, int y) {
        int i = 3 * ((height - 1 - y) * width + x);
        return new float[] {pfm[i], pfm[i + 1], pfm[i + 2]};
    }

    @ParameterizedTest
    @ValueSource(strings = {"cook-torrance", "phong", PATH})
    void aSphereOf1eMinus20LitFromNearIsTheLargestFloatWhereLit(String model) throws IOException {
        // the light 2.2e-20 from the sphere's front: irradiance 100 / 5e-40 x cos 0.89 = 1.8e41, past a float
        float[] image = render("""
                camera: {position: [0, 0, -5e-20], look_at: [0, 0, 0]}
                lights:
                  - {type: point, position: [0, 1e-20, -3e-20], intensity: 100}
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1e-20}
                """, model, 32, 24);
        float[] centre = pixel(image, 32, 24, 16, 12);
        assertEquals(LARGEST, centre[0]);
        assertEquals(LARGEST, centre[1]);
        assertEquals(LARGEST, centre[2]);
        assertEquals(0f, pixel(image, 32, 24, 0, 0)[0]); // the corner sees the black sky
    }

    @ParameterizedTest
    @ValueSource(strings = {"cook-torrance", "phong", PATH})
    void aColourOf1e30UnderAnAmbientOf1e30IsTheLargestFloatAndItsBlackChannelStaysBlack(String model)
            throws IOException {
        // matte: 1e30 x 1e30 = 1e60 in red and blue; green 0 x 1e30 = 0 (phong: kd 0.99 of the same); the
        // path integrator has no ambient light: black
        float[] image = render("""
                ambient: [1e30, 1e30, 1e30]
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: matte, color: [1e30, 0, 1e30]}}
                """, model, 32, 24);
        float[] centre = pixel(image, 32, 24, 16, 12);
        assertEquals(model.equals(PATH) ? 0f : LARGEST, centre[0]);
        assertEquals(0f, centre[1]);
        assertEquals(model.equals(PATH) ? 0f : LARGEST, centre[2]);
    }

    @ParameterizedTest
    @ValueSource(strings = {"cook-torrance", "phong", PATH})
    void aPhongGlassOfKs1e6ThroughSixtyFourBouncesStaysFinite(String model) throws IOException {
        // in phong each reflection inside the glass multiplies the light by 1e6: 1e384 after 64, past a
        // double. Its tint has no green, so green comes back only from the front face, 1e6 x what it
        // mirrors (a floor and sky of radiance below 10), and the green inside counts 0 x (more than a
        // double), which must be 0, not NaN. Cook-torrance's glass has no ks: the front face reflects
        // its Fresnel share (4 % at normal incidence)
        float[] image = render("""
                lights:
                  - {type: point, position: [0, 5, -5], intensity: 100}
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: glass, ks: 1e6, color: [1, 0, 1]}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                """, model, 32, 24);
        float[] centre = pixel(image, 32, 24, 16, 12);
        if (model.equals("phong")) {
            assertEquals(LARGEST, centre[0]);
            assertEquals(LARGEST, centre[2]);
            assertTrue(centre[1] > 0 && centre[1] < 1e7, "green mirrored by the front face: " + centre[1]);
        } else if (model.equals(PATH)) { // one random path of the sky (black), the floor or the light
            assertTrue(centre[0] < 1, "a clear glass in front of a lit floor: " + centre[0]);
        } else { // the sky behind is black: what the centre shows is the front face's reflection, untinted
            assertTrue(centre[0] > 0 && centre[0] < 1, "mirrored by the front face: " + centre[0]);
            assertEquals(centre[0], centre[1]);
            assertEquals(centre[0], centre[2]);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"cook-torrance", "phong", PATH})
    void aLightOf1e30On1e140OffTheSurfaceIsTheLargestFloatAndNotNaN(String model) throws IOException {
        // the one pixel's ray meets the plane at (0, 1, 0), 1e-140 from the light: 1e30 / 1e-280 is past a
        // double, so a factor of 0 (green's albedo) would make it NaN (the path integrator's one sample
        // is not at the pixel's centre, where the light is: only finite)
        float[] image = render("""
                lights:
                  - {type: point, position: [0, 1, -1e-140], intensity: 1e30}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 0, -1], material: {type: matte, color: [0.5, 0, 0.5]}}
                """, model, 1, 1);
        if (model.equals(PATH)) {
            return;
        }
        assertEquals(LARGEST, image[0]);
        assertEquals(LARGEST, image[2]);
        // green: 0 of a matte surface in cook-torrance; in phong the white highlight, ks 0.01 of it
        assertEquals(model.equals("phong") ? LARGEST : 0f, image[1]);
    }

    /**
     * A closed room whose walls (and a ball in it, which casts a shadow) reflect 1e30 times the light they
     * get, at depth 64 in the path integrator: every bounce multiplies a path's weight by about 1e30, past a
     * double after ten, and a vertex in the shadow adds nothing (infinity x 0 would be NaN); every pixel is
     * the largest float, never black.
     */
    @Test
    void aClosedRoomOfColour1e30IsTheLargestFloatInThePathIntegrator() throws IOException {
        String wall = "material: {type: matte, color: [1e30, 1e30, 1e30]}}";
        float[] image = render("""
                camera: {position: [0, 1, -1.5], look_at: [0, 1, 0]}
                lights:
                  - {type: point, position: [0, 1.9, 1.5], intensity: 10}
                objects:
                  - {type: sphere, center: [0, 1, 0.8], radius: 0.6, WALL
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], WALL
                  - {type: plane, point: [0, 2, 0], normal: [0, -1, 0], WALL
                  - {type: plane, point: [-2, 0, 0], normal: [1, 0, 0], WALL
                  - {type: plane, point: [2, 0, 0], normal: [-1, 0, 0], WALL
                  - {type: plane, point: [0, 0, -2], normal: [0, 0, 1], WALL
                  - {type: plane, point: [0, 0, 2], normal: [0, 0, -1], WALL
                """.replace("WALL", wall), PATH, 8, 6);
        for (int i = 0; i < image.length; i++) {
            assertEquals(LARGEST, image[i], "value " + i);
        }
    }
}
