package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.geometry.Hit;
import glint.shading.LightSample;
import glint.shading.Lobe;
import glint.shading.Surface;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The light loop reaches through a surface whose lobes send light through it: a ray inside a rough
 * glass ball meets its wall, and a light outside, behind that wall, reaches the point by a shadow
 * ray that leaves from the far side, at cosine |n.l|; smooth glass has no such lobe, and a light
 * behind any other surface does not reach it.
 */
class LightThroughSurfaceTest {

    private static final String BALL = """
            lights:
              - {type: point, position: [0, 0, 5], LIGHT}
            objects:
              - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: glass, roughness: ROUGHNESS}}
            """;

    @ParameterizedTest
    @ValueSource(strings = {"intensity: 4", "radius: 0.5, intensity: 4"})
    void aLightBehindTheWallOfARoughGlassBallReachesItsInsideFromTheFarSide(String light) {
        PathIntegrator integrator = wallSeenFromInside(BALL.replace("LIGHT", light).replace("ROUGHNESS", "0.3"));
        Surface s = wall;
        assertTrue(Lobe.transmitsNonDelta(integrator.materials.lobes(s.material)));
        assertTrue(s.nz < 0, "the normal faces the ray, inwards: " + s.nz);
        LightSample out = new LightSample();
        integrator.beginPath(0, 0, 0, 1);
        double pass = integrator.lightReaching(s, 0, true, out);
        assertEquals(1, pass, "nothing but the wall lies between");
        assertEquals(-(out.dirX * s.nx + out.dirY * s.ny + out.dirZ * s.nz), out.cosine, 1e-12);
        assertTrue(out.cosine > 0.9);
        integrator.beginPath(0, 0, 0, 1);
        assertEquals(0, integrator.lightReaching(s, 0, false, out), "not asked to reach through");
    }

    @ParameterizedTest
    @ValueSource(strings = {"intensity: 4", "radius: 0.5, intensity: 4"})
    void smoothGlassHasNoLobeThatALightSampleReachesThrough(String light) {
        PathIntegrator integrator = wallSeenFromInside(BALL.replace("LIGHT", light).replace("ROUGHNESS", "0"));
        assertFalse(Lobe.transmitsNonDelta(integrator.materials.lobes(wall.material)));
    }

    private final Surface wall = new Surface();

    /** A path integrator on the scene, with {@link #wall} the ball's wall at (0, 0, 1) met from its centre. */
    private PathIntegrator wallSeenFromInside(String yaml) {
        RenderScene scene = RenderScene.compile(Renders.scene(yaml),
                new RenderSettings(Shading.COOK_TORRANCE, 4, 0, Renders.EPSILON).withTransport(LightTransport.PATH));
        PathIntegrator integrator = new PathIntegrator();
        integrator.prepare(scene);
        Hit hit = new Hit();
        assertTrue(integrator.nearest(0, 0, 0, 0, 0, 1, Hit.NONE, 0, hit));
        integrator.describe(hit, 0, 0, 0, 0, 0, 1, wall);
        assertFalse(wall.front);
        return integrator;
    }
}
