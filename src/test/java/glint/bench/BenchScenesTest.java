package glint.bench;

import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.scene.Light;
import glint.scene.Scene;
import glint.scene.SceneObject;
import glint.scenefile.SceneLoader;
import org.junit.jupiter.api.Test;

class BenchScenesTest {

    @Test
    void everyHandWrittenSceneLoads() throws Exception {
        for (String name : BenchScenes.HAND_WRITTEN) {
            Scene scene = SceneLoader.load(BenchScenes.file(name));
            assertTrue(scene.objects().size() > 0, name);
        }
    }

    @Test
    void lamplightHoldsEverythingWithASize() throws Exception {
        Scene scene = SceneLoader.load(BenchScenes.file("lamplight"));
        assertTrue(scene.lights().stream().anyMatch(l -> l instanceof Light.Point p && p.radius() > 0), "a sphere light");
        assertTrue(scene.lights().stream().anyMatch(l -> l instanceof Light.Directional d && d.angleDegrees() > 0),
                "a sun with an angle");
        assertTrue(scene.camera().aperture() > 0, "a thin lens");
        assertTrue(scene.objects().stream().map(SceneObject::material)
                .anyMatch(m -> m.type().equals("glass") && m.parameter("roughness") > 0), "frosted glass");
        assertTrue(scene.objects().stream().map(SceneObject::material)
                .anyMatch(m -> m.type().equals("metal") && m.parameter("roughness") > 0), "a rough metal");
        assertTrue(scene.objects().stream().map(SceneObject::material)
                .anyMatch(m -> m.type().equals("metal") && m.parameter("roughness") == 0), "a mirror");
    }
}
