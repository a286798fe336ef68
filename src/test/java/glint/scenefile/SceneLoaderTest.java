package glint.scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.registry.GlassType;
import glint.registry.MatteType;
import glint.registry.MetalType;
import glint.scene.Camera;
import glint.scene.Light;
import glint.scene.Material;
import glint.scene.Plane;
import glint.scene.Scene;
import glint.scene.Sphere;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** Scenes that load: defaults, normalisation, materials, lights, the camera, the shipped scenes. */
class SceneLoaderTest {

    private static final double EPS = 1e-12;

    private static Scene parse(String text) throws InputException {
        return SceneLoader.parse("test.yaml", text);
    }

    private static void assertVector(Vector3d expected, Vector3d actual) {
        assertEquals(expected.x(), actual.x(), EPS, () -> "x of " + actual);
        assertEquals(expected.y(), actual.y(), EPS, () -> "y of " + actual);
        assertEquals(expected.z(), actual.z(), EPS, () -> "z of " + actual);
    }

    private static Vector3d v(double x, double y, double z) {
        return new Vector3d(x, y, z);
    }

    private static Material material(Scene scene, int object) {
        return scene.objects().get(object).material();
    }

    // ---------------------------------------------------------------- defaults

    @Test
    void emptyCameraMappingTakesEveryDefault() throws InputException {
        Scene scene = parse("camera: {}\n");
        Camera camera = scene.camera();
        assertVector(v(0, 1, -5), camera.position());
        assertEquals(60, camera.fovDegrees());
        assertVector(Vector3d.UNIT_Z, camera.orientation().forward());
        assertVector(Vector3d.UNIT_Y, camera.orientation().up());
        assertVector(Vector3d.UNIT_X, camera.orientation().right());
        assertEquals(Camera.defaults().position(), camera.position());
    }

    @Test
    void cameraKeyWithNothingAfterItTakesEveryDefault() throws InputException {
        Scene scene = parse("camera:\nobjects: []\n");
        assertEquals(Camera.defaults(), scene.camera());
    }

    @Test
    void sceneWithoutCameraTakesTheDefaults() throws InputException {
        Scene scene = parse("objects: []\n");
        assertEquals(Camera.defaults(), scene.camera());
        assertEquals(Vector3d.ZERO, scene.background());
        assertEquals(Vector3d.ZERO, scene.ambient());
        assertTrue(scene.lights().isEmpty());
        assertTrue(scene.objects().isEmpty());
    }

    @Test
    void emptyListsAreAllowed() throws InputException {
        Scene scene = parse("lights:\nobjects:\nmaterials:\n");
        assertTrue(scene.lights().isEmpty());
        assertTrue(scene.objects().isEmpty());
    }

    @Test
    void objectWithoutMaterialIsMatte() throws InputException {
        Scene scene = parse("objects:\n  - {type: sphere, center: [0, 0, 0], radius: 1}\n");
        Material m = material(scene, 0);
        assertEquals(MatteType.TYPE.preset(), m);
        assertEquals("matte", m.type());
        assertEquals(v(0.8, 0.8, 0.8), m.color());
    }

    @Test
    void presetsHaveTheSpecValues() throws InputException {
        Scene scene = parse("""
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: matte}
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: metal}
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: glass}
                """);
        assertEquals(new Material("matte", v(0.8, 0.8, 0.8), 0.99, 0.01, 0, 10),
                material(scene, 0));
        assertEquals(new Material("metal", v(0.9, 0.9, 0.9), 0.1, 0.7, 0, 50, Map.of("roughness", 0.0)),
                material(scene, 1));
        assertEquals(new Material("glass", v(1, 1, 1), 0.01, 0.2, 0.79, 125, Map.of("ior", 1.5, "roughness", 0.0)),
                material(scene, 2));
    }

    @Test
    void lightDefaults() throws InputException {
        Scene scene = parse("""
                lights:
                  - {type: point, position: [1, 2, 3]}
                  - {type: directional, direction: [0, -1, 0]}
                """);
        Light.Point point = assertInstanceOf(Light.Point.class, scene.lights().get(0));
        assertEquals(v(1, 2, 3), point.position());
        assertEquals(Vector3d.ONE, point.color());
        assertEquals(1, point.intensity());
        Light.Directional directional = assertInstanceOf(Light.Directional.class, scene.lights().get(1));
        assertEquals(Vector3d.ONE, directional.color());
        assertEquals(1, directional.intensity());
    }

    // ---------------------------------------------------------------- values

    @Test
    void everyCameraKey() throws InputException {
        Scene scene = parse("""
                camera:
                  position: [1, 2, 3]
                  look_at: [4, 6, 3]
                  up: [0, 0, 1]
                  fov: 45.5
                """);
        Camera camera = scene.camera();
        assertVector(v(1, 2, 3), camera.position());
        assertEquals(45.5, camera.fovDegrees());
        assertVector(v(0.6, 0.8, 0), camera.orientation().forward());
        // up is made perpendicular to forward; [0, 0, 1] already is
        assertVector(v(0, 0, 1), camera.orientation().up());
    }

    @Test
    void lookAtOrientsTheCamera() throws InputException {
        Vector3d position = v(-3, 2.5, -7);
        Vector3d lookAt = v(1, 0.25, 2);
        Scene scene = parse("""
                camera:
                  position: [-3, 2.5, -7]
                  look_at: [1, 0.25, 2]
                """);
        Vector3d expected = lookAt.sub(position).normalize();
        Vector3d forward = scene.camera().orientation().forward();
        assertVector(expected, forward);
        assertEquals(1, forward.length(), EPS);
        // the default up [0, 1, 0] keeps the camera level: its right vector is horizontal
        assertEquals(0, scene.camera().orientation().right().y(), EPS);
        assertTrue(scene.camera().orientation().up().y() > 0);
    }

    @Test
    void lookAtWithoutPositionLooksFromTheDefaultPosition() throws InputException {
        Scene scene = parse("camera: {look_at: [0, 1, 0]}\n");
        assertVector(v(0, 1, -5), scene.camera().position());
        assertVector(Vector3d.UNIT_Z, scene.camera().orientation().forward());
    }

    @Test
    void positionWithoutLookAtLooksAlongPlusZ() throws InputException {
        Scene scene = parse("camera: {position: [3, 4, 5]}\n");
        assertVector(v(3, 4, 5), scene.camera().position());
        assertVector(Vector3d.UNIT_Z, scene.camera().orientation().forward());
    }

    @Test
    void backgroundAndAmbient() throws InputException {
        Scene scene = parse("background: [0.02, 0.02, 0.04]\nambient: [0, 0.5, 1]\n");
        assertEquals(v(0.02, 0.02, 0.04), scene.background());
        assertEquals(v(0, 0.5, 1), scene.ambient());
    }

    @Test
    void numbersMayBeIntegersDecimalsOrExponents() throws InputException {
        Scene scene = parse("""
                objects:
                  - {type: sphere, center: [1, -2.5, +3.], radius: 2e-1}
                  - {type: sphere, center: [.5, 0, -0], radius: 1E2}
                """);
        Sphere a = assertInstanceOf(Sphere.class, scene.objects().get(0).shape());
        assertEquals(v(1, -2.5, 3), a.center());
        assertEquals(0.2, a.radius());
        Sphere b = assertInstanceOf(Sphere.class, scene.objects().get(1).shape());
        assertEquals(v(0.5, 0, -0.0), b.center());
        assertEquals(100, b.radius());
    }

    @Test
    void blockAndFlowStylesGiveTheSameScene() throws InputException {
        Scene flow = parse("objects: [{type: sphere, center: [0, 1, 0], radius: 1, material: metal}]\n");
        Scene block = parse("""
                objects:
                  - type: sphere
                    center:
                      - 0
                      - 1
                      - 0
                    radius: 1
                    material: metal
                """);
        assertEquals(flow, block);
    }

    @Test
    void planeNormalIsNormalisedOnLoad() throws InputException {
        Scene scene = parse("""
                objects:
                  - {type: plane, point: [0, -1, 0], normal: [0, 2, 0]}
                  - {type: plane, point: [1, 2, 3], normal: [3, 0, -4]}
                """);
        Plane floor = assertInstanceOf(Plane.class, scene.objects().get(0).shape());
        assertEquals(v(0, -1, 0), floor.point());
        assertVector(v(0, 1, 0), floor.normal());
        Plane tilted = assertInstanceOf(Plane.class, scene.objects().get(1).shape());
        assertEquals(v(1, 2, 3), tilted.point());
        assertVector(v(0.6, 0, -0.8), tilted.normal());
        assertEquals(1, tilted.normal().length(), EPS);
    }

    @Test
    void directionalLightDirectionIsNormalised() throws InputException {
        Scene scene = parse("""
                lights:
                  - {type: directional, direction: [0, -3, 4], color: [1, 0.9, 0.8], intensity: 2.5}
                """);
        Light.Directional light = assertInstanceOf(Light.Directional.class, scene.lights().get(0));
        assertVector(v(0, -0.6, 0.8), light.direction());
        assertEquals(v(1, 0.9, 0.8), light.color());
        assertEquals(2.5, light.intensity());
    }

    @Test
    void pointLight() throws InputException {
        Scene scene = parse("lights:\n  - {type: point, position: [-5, 8, -6], color: [1, 0.5, 0], intensity: 0}\n");
        assertEquals(new Light.Point(v(-5, 8, -6), v(1, 0.5, 0), 0), scene.lights().get(0));
    }

    @Test
    void sphere() throws InputException {
        Scene scene = parse("objects:\n  - {type: sphere, center: [-2.2, 1, 0], radius: 0.75}\n");
        assertEquals(new Sphere(v(-2.2, 1, 0), 0.75), scene.objects().get(0).shape());
    }

    // ---------------------------------------------------------------- materials

    @Test
    void inlineMaterialOverridesEveryCoefficient() throws InputException {
        Scene scene = parse("""
                objects:
                  - type: sphere
                    center: [0, 0, 0]
                    radius: 1
                    material:
                      type: metal
                      color: [0.1, 0.2, 0.3]
                      kd: 0.3
                      ks: 0.5
                      kt: 0.1
                      shininess: 20
                      roughness: 0.5
                  - type: sphere
                    center: [0, 0, 0]
                    radius: 1
                    material: {type: glass, color: [0.4, 0.5, 0.6], kd: 0.2, ks: 0.3, kt: 0.4, shininess: 30, ior: 1.2}
                """);
        // a metal has no ior (phong refracts its kt at 1.5), a glass keeps its preset's roughness 0
        assertEquals(new Material("metal", v(0.1, 0.2, 0.3), 0.3, 0.5, 0.1, 20, Map.of("roughness", 0.5)),
                material(scene, 0));
        assertEquals(1.5, MetalType.TYPE.compile(material(scene, 0)).ior());
        assertEquals(new Material("glass", v(0.4, 0.5, 0.6), 0.2, 0.3, 0.4, 30, Map.of("ior", 1.2, "roughness", 0.0)),
                material(scene, 1));
    }

    @Test
    void inlineMaterialKeepsThePresetForWhatItDoesNotSay() throws InputException {
        Scene scene = parse("""
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: glass, kt: 0.5}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.5, 0.5]}}
                """);
        Material glass = GlassType.TYPE.preset();
        assertEquals(new Material("glass", glass.color(), glass.kd(), glass.ks(), 0.5, glass.shininess(),
                glass.parameters()), material(scene, 0));
        Material matte = MatteType.TYPE.preset();
        assertEquals(new Material("matte", v(0.5, 0.5, 0.5), matte.kd(), matte.ks(), matte.kt(),
                matte.shininess(), matte.parameters()), material(scene, 1));
    }

    @Test
    void roughnessMayBeZeroOrOne() throws InputException {
        Scene scene = parse("""
                materials:
                  mirror: {type: metal, roughness: 0}
                  rough: {type: metal, roughness: 1}
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: mirror}
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: rough}
                """);
        assertEquals(0, material(scene, 0).parameter("roughness"));
        assertEquals(1, material(scene, 1).parameter("roughness"));
    }

    @Test
    void glassReadsRoughnessBesidesIor() throws InputException {
        Scene scene = parse("""
                materials:
                  frost: {type: glass, roughness: 0.25, ior: 1.33}
                  edge: {type: glass, roughness: 1}
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: frost}
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: edge}
                """);
        assertEquals(0.25, material(scene, 0).parameter("roughness"));
        assertEquals(1.33, material(scene, 0).parameter("ior"));
        assertEquals(1, material(scene, 1).parameter("roughness"));
        assertEquals(1.5, material(scene, 1).parameter("ior"));
    }

    @Test
    void namedMaterialsAreSharedByName() throws InputException {
        Scene scene = parse("""
                objects:
                  - {type: sphere, center: [-2, 1, 0], radius: 1, material: red}
                  - {type: sphere, center: [2, 1, 0], radius: 1, material: gold}
                  - {type: sphere, center: [0, 3, 0], radius: 1, material: red}
                materials:
                  red:   {type: matte, color: [0.8, 0.1, 0.1]}
                  gold:  {type: metal, color: [1.0, 0.77, 0.34], roughness: 0.05}
                """);
        Material red = material(scene, 0);
        assertEquals("matte", red.type());
        assertEquals(v(0.8, 0.1, 0.1), red.color());
        assertEquals(0.99, red.kd());
        Material gold = material(scene, 1);
        assertEquals(new Material("metal", v(1.0, 0.77, 0.34), 0.1, 0.7, 0, 50, Map.of("roughness", 0.05)), gold);
        assertSame(red, material(scene, 2));
    }

    @Test
    void anchorsAndAliasesWork() throws InputException {
        Scene scene = parse("""
                objects:
                  - {type: sphere, center: &c [0, 1, 0], radius: 1}
                  - {type: sphere, center: *c, radius: 2}
                """);
        assertEquals(v(0, 1, 0), ((Sphere) scene.objects().get(1).shape()).center());
    }

    @Test
    void theSpecExampleLoads() throws InputException {
        Scene scene = parse("""
                camera:                         # all keys optional
                  position: [0, 1, -5]          # default [0, 1, -5]
                  look_at:  [0, 1, 0]           # default position + [0, 0, 1]
                  up:       [0, 1, 0]           # default [0, 1, 0]
                  fov: 60                       # horizontal field of view in degrees, default 60
                background: [0.02, 0.02, 0.04]  # linear RGB radiance of a ray that hits nothing, default [0,0,0]
                ambient: [0, 0, 0]              # linear RGB; adds ambient x albedo at matte hits, default [0,0,0]
                lights:
                  - {type: point, position: [-5, 8, -6], color: [1, 1, 1], intensity: 100}
                  - {type: directional, direction: [0, -1, 0.2], color: [1, 1, 1], intensity: 2}
                materials:                      # named materials; the presets matte, metal, glass always exist
                  red:   {type: matte, color: [0.8, 0.1, 0.1]}
                  gold:  {type: metal, color: [1.0, 0.77, 0.34], roughness: 0.05}
                  clear: {type: glass, ior: 1.5}
                objects:
                  - {type: sphere, center: [-2.2, 1, 0], radius: 1, material: red}
                  - {type: sphere, center: [0, 1, 0], radius: 1, material: clear}
                  - {type: sphere, center: [2.2, 1, 0], radius: 1, material: gold}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.5, 0.5]}}
                """);
        assertEquals(2, scene.lights().size());
        assertEquals(4, scene.objects().size());
        assertEquals(Camera.defaults().withLens(0, 5), scene.camera()); // the default pose, focused on its look_at
        Light.Directional sun = (Light.Directional) scene.lights().get(1);
        assertVector(v(0, -1, 0.2).normalize(), sun.direction());
        assertEquals(GlassType.TYPE.preset(), material(scene, 1));
    }

    // ---------------------------------------------------------------- shipped scenes

    @Test
    void theSpecsExampleSceneLoads() throws InputException {
        Scene scene = SceneLoader.load(Path.of("scenes", "bench", "spec-example.yaml"));
        assertEquals(1, scene.lights().size());
        assertEquals(4, scene.objects().size());
        assertInstanceOf(Light.Point.class, scene.lights().get(0));
        long spheres = scene.objects().stream().filter(o -> o.shape() instanceof Sphere).count();
        assertEquals(3, spheres);
        assertEquals(List.of("matte", "glass", "metal", "matte"),
                scene.objects().stream().map(o -> o.material().type()).toList());
        Camera camera = scene.camera();
        assertTrue(camera.fovDegrees() > 0 && camera.fovDegrees() < 180);
        assertEquals(1, camera.orientation().forward().length(), EPS);
    }

    @Test
    void everySceneInTheRepositoryLoads() throws IOException, InputException {
        List<Path> scenes;
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            scenes = files.filter(p -> p.toString().endsWith(".yaml")).sorted().toList();
        }
        assertTrue(scenes.contains(Path.of("scenes", "default.yaml")), () -> "scenes: " + scenes);
        for (Path path : scenes) {
            Scene scene = SceneLoader.load(path);
            assertTrue(scene.camera().fovDegrees() > 0, path::toString);
        }
    }

    // ---------------------------------------------------------------- numbers at the edge of double

    @Test
    void hugeDirectionsAndNormalsAreScaledBeforeTheyAreNormalised() throws InputException {
        // |(1e200, -1e200, 0)| overflows to infinity: normalised as is, the light would vanish (a zero direction)
        Scene scene = SceneLoader.parse("edge", """
                lights:
                  - {type: directional, direction: [1e200, -1e200, 0]}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1e200, 1e200]}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1e-200, 0]}
                """);
        double half = Math.sqrt(0.5);
        Light.Directional light = assertInstanceOf(Light.Directional.class, scene.lights().get(0));
        assertVector(v(half, -half, 0), light.direction());
        assertVector(v(0, half, half), ((Plane) scene.objects().get(0).shape()).normal());
        // |(0, 1e-200, 0)| squared underflows to 0: it would be taken for the zero vector
        assertVector(v(0, 1, 0), ((Plane) scene.objects().get(1).shape()).normal());
    }

    @Test
    void ordinaryDirectionsAreNormalisedExactlyAsBefore() throws InputException {
        // scaling first would change the last bit of some; a direction of ordinary size is left alone
        Vector3d d = new Vector3d(0.3, -1.7, 2.9);
        Scene scene = SceneLoader.parse("ordinary", "lights:\n  - {type: directional, direction: [0.3, -1.7, 2.9]}\n");
        assertEquals(d.normalize(), ((Light.Directional) scene.lights().get(0)).direction());
    }

    @Test
    void aHugeUpVectorIsNotTakenForParallel() throws InputException {
        Scene scene = SceneLoader.parse("up", "camera: {position: [0, 0, -5], look_at: [0, 0, 0], up: [0, 1e300, 0]}\n");
        Scene plain = SceneLoader.parse("up", "camera: {position: [0, 0, -5], look_at: [0, 0, 0], up: [0, 1, 0]}\n");
        assertEquals(plain.camera(), scene.camera());
    }
}
