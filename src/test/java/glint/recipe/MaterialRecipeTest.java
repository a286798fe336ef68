package glint.recipe;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.render.FrameBuffer;
import glint.registry.Registry;
import org.junit.jupiter.api.Test;

/** The material recipe followed in test sources: a glowing material read, compiled and rendered. */
class MaterialRecipeTest {

    private static final Registry REGISTRY = Registry.STANDARD.with(Glow.TYPE);

    @Test
    void aGlowingSphereShowsItsColourWithNoLightAtAll() {
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 10}
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1, material: {type: glow, color: [0.3, 0.6, 0.9]}}
                """;
        FrameBuffer frame = Recipes.render(REGISTRY, yaml, 9, 9, 3);
        assertEquals(0.3f, frame.get(4, 4, 0));
        assertEquals(0.6f, frame.get(4, 4, 1));
        assertEquals(0.9f, frame.get(4, 4, 2));
    }

    @Test
    void aWhiteMirrorShowsTheGlowBehindTheCameraAndOnlyWhenItsRayIsFollowed() {
        // the centre ray meets the mirror head-on and returns along -z to the glowing plane z = -10;
        // Schlick's Fresnel with F0 = 1 is 1 at every angle
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 10}
                materials:
                  warm: {type: glow, color: [1, 0.5, 0.25]}
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1, material: {type: metal, color: [1, 1, 1]}}
                  - {type: plane, point: [0, 0, -10], normal: [0, 0, 1], material: warm}
                """;
        FrameBuffer mirrored = Recipes.render(REGISTRY, yaml, 9, 9, 2);
        assertEquals(1f, mirrored.get(4, 4, 0));
        assertEquals(0.5f, mirrored.get(4, 4, 1));
        assertEquals(0.25f, mirrored.get(4, 4, 2));
        FrameBuffer direct = Recipes.render(REGISTRY, yaml, 9, 9, 1);
        assertEquals(0f, direct.get(4, 4, 0), "depth 1 follows no reflection");
    }

    @Test
    void theNewTypeIsAPresetAndAHintLikeTheOthers() {
        String yaml = """
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1, material: glow}
                """;
        assertEquals(Glow.TYPE.preset(), Recipes.scene(REGISTRY, yaml).objects().get(0).material());
        assertEquals("recipe.yaml:2:15: unknown material type 'glwo' (did you mean 'glow'?)",
                Recipes.error(REGISTRY, "materials:\n  hot: {type: glwo}\n"));
        assertEquals("recipe.yaml:2:3: material name 'glow' is a preset and cannot be redefined (choose another name)",
                Recipes.error(REGISTRY, "materials:\n  glow: {type: matte}\n"));
    }
}
