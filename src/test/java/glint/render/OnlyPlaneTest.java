package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Shading;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * A ray that leaves a scene's only plane has no plane to test ({@link RayCaster#noPlaneToTest}): the
 * shortcut holds for exactly those rays, and a frame that takes it matches one that cannot.
 */
class OnlyPlaneTest {

    private static final String SPHERE = "  - {type: sphere, center: [0, 1, 0], radius: 1}\n";
    private static final String FLOOR = "  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}\n";
    private static final String WALL = "  - {type: plane, point: [0, 0, 9], normal: [0, 0, -1]}\n";

    private static RenderScene compile(String objects) {
        String yaml = "lights: [{type: point, position: [2, 5, -3]}]\nobjects:\n" + objects;
        return RenderScene.compile(Renders.scene(yaml), new RenderSettings(Shading.COOK_TORRANCE, 5, 0, 1e-9));
    }

    /** The skip codes of rays leaving the sphere outwards, inwards, plane 0, plane 1, from the eye and of none. */
    private static final int[] CODES = {RayCaster.surfaceId(0, -1), RayCaster.insideOf(0), RayCaster.surfaceId(-1, 0),
            RayCaster.surfaceId(-1, 1), Integer.MIN_VALUE, 0};

    @Test
    void onlyARayLeavingTheOnePlaneSkipsThePlanes() {
        RenderScene onePlane = compile(SPHERE + FLOOR);
        for (int code : CODES) {
            assertEquals(code == RayCaster.surfaceId(-1, 0), RayCaster.noPlaneToTest(onePlane, code), "code " + code);
        }
    }

    @Test
    void withTwoPlanesEveryRayTestsOne() {
        RenderScene twoPlanes = compile(SPHERE + FLOOR + WALL);
        for (int code : CODES) {
            assertFalse(RayCaster.noPlaneToTest(twoPlanes, code), "code " + code);
        }
    }

    @Test
    void withoutPlanesNoRayTestsOne() {
        RenderScene noPlane = compile(SPHERE);
        for (int code : CODES) {
            assertTrue(RayCaster.noPlaneToTest(noPlane, code), "code " + code);
        }
    }

    /**
     * The default scene with a second plane far below its floor, which no ray can reach (the floor
     * is in the way of every ray going down, and the light is above both): every floor hit then
     * tests the planes, and the image and the rays cast stay the same.
     */
    @Test
    void aPlaneNoRayReachesChangesNoPixel() throws IOException {
        String scene = Files.readString(Path.of("scenes/default.yaml"));
        String deep = scene + "  - {type: plane, point: [0, -1000, 0], normal: [0, 1, 0]}\n";
        FrameBuffer shortcut = new FrameBuffer(160, 120);
        FrameBuffer full = new FrameBuffer(160, 120);
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 5, 0.01, 1e-9);
        long shortcutRays = Renders.renderCountingRays(RenderScene.compile(Renders.scene(scene), settings), shortcut, 4);
        long fullRays = Renders.renderCountingRays(RenderScene.compile(Renders.scene(deep), settings), full, 4);
        assertArrayEquals(full.rgb(), shortcut.rgb());
        assertEquals(fullRays, shortcutRays);
    }
}
