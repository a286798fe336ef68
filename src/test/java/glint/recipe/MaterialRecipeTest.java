package glint.recipe;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import glint.image.FrameBuffer;
import glint.math.Vector3d;
import glint.registry.GlassType;
import glint.registry.MaterialType;
import glint.registry.MatteType;
import glint.registry.MetalType;
import glint.registry.Registry;
import glint.scene.Material;
import glint.shading.Dielectric;
import glint.shading.GlassResponse;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The material recipe followed in test sources: a glowing material read, compiled and rendered. */
class MaterialRecipeTest {

    private static final Registry REGISTRY = Registry.STANDARD.with(GlowType.TYPE);

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

    /** Its own key, which no shipped type reads, read, compiled and read by its BSDF: twice the colour. */
    @Test
    void aGlowOfStrengthTwoShowsTwiceItsColour() {
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 10}
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1, material: {type: glow, color: [0.3, 0.6, 0.9], strength: 2}}
                """;
        Material glow = Recipes.scene(REGISTRY, yaml).objects().get(0).material();
        assertEquals(new Material("glow", new Vector3d(0.3, 0.6, 0.9), 0, 0, 0, 1, Map.of("strength", 2.0)), glow);
        assertArrayEquals(new double[] {2}, GlowType.TYPE.compile(glow).parameters());
        FrameBuffer frame = Recipes.render(REGISTRY, yaml, 9, 9, 3);
        assertEquals(0.6f, frame.get(4, 4, 0));
        assertEquals(1.2f, frame.get(4, 4, 1));
        assertEquals(1.8f, frame.get(4, 4, 2));
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
        assertEquals(GlowType.TYPE.preset(), Recipes.scene(REGISTRY, yaml).objects().get(0).material());
        assertEquals("recipe.yaml:2:15: unknown material type 'glwo' (did you mean 'glow'?)",
                Recipes.error(REGISTRY, "materials:\n  hot: {type: glwo}\n"));
        assertEquals("recipe.yaml:2:3: material name 'glow' is a preset and cannot be redefined (choose another name)",
                Recipes.error(REGISTRY, "materials:\n  glow: {type: matte}\n"));
    }

    @Test
    void theNewTypeReadsItsOwnKeysAndAKeyOfAnotherTypeIsRefusedNamingItAndTheFix() {
        assertEquals("recipe.yaml:2:19: a glow material has no roughness (roughness is a key of metal and glass; "
                        + "write type: metal or type: glass, or remove roughness)",
                Recipes.error(REGISTRY, "materials:\n  m: {type: glow, roughness: 0.5}\n"));
        assertEquals("recipe.yaml:2:20: a matte material has no strength (strength is a key of glow; write type: glow, "
                        + "or remove strength)",
                Recipes.error(REGISTRY, "materials:\n  m: {type: matte, strength: 2}\n"));
        assertEquals("recipe.yaml:2:29: strength must lie in [0, 1e30], got -1",
                Recipes.error(REGISTRY, "materials:\n  m: {type: glow, strength: -1}\n"));
        // a second type reading ior: both are named
        MaterialType lens = lens();
        assertEquals("recipe.yaml:2:19: a glow material has no ior (ior is a key of glass and lens; write type: glass "
                        + "or type: lens, or remove ior)",
                Recipes.error(REGISTRY.with(lens), "materials:\n  m: {type: glow, ior: 1.2}\n"));
        assertEquals("recipe.yaml:2:19: unknown key 'iro' in material 'm' (expected one of: type, color, kd, ks, kt, "
                        + "shininess, strength)",
                Recipes.error(REGISTRY.with(lens), "materials:\n  m: {type: glow, iro: 1.2}\n"));
    }

    @Test
    void aTypeReadsAnyKeyButACommonOneOrOneItReadsAlready() {
        MaterialType plain = new MaterialType("plain", new Glow(), GlowType.NO_RAYS, Vector3d.ONE, 0, 0, 0, 1);
        assertEquals("material type plain cannot read kd of its own: every type reads it",
                assertThrows(IllegalArgumentException.class, () -> plain.reads("kd", 1, (fields, key) -> 1))
                        .getMessage());
        assertEquals("material type glow cannot read strength of its own: it reads it already",
                assertThrows(IllegalArgumentException.class, () -> GlowType.TYPE.reads("strength", 1,
                        (fields, key) -> 1)).getMessage());
    }

    /** A lens reading ior alone, compiled for the glass BSDF it borrows (smooth). */
    private static MaterialType lens() {
        return new MaterialType("lens", new Dielectric(), new GlassResponse(), Vector3d.ONE, 0, 0, 1, 1)
                .reads("ior", 1.5, GlassType::ior)
                .compiledBy(m -> Dielectric.parameters(m.parameter("ior"), 0));
    }

    @Test
    void aTypeReadsItsKeysWithTheReaderItIsGiven() {
        MaterialType lens = lens();
        Registry registry = REGISTRY.with(lens);
        String yaml = """
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1, material: {type: lens, ior: 1.25, ks: 0.5}}
                """;
        Material read = Recipes.scene(registry, yaml).objects().get(0).material();
        assertEquals(new Material("lens", Vector3d.ONE, 0, 0.5, 1, 1, Map.of("ior", 1.25)), read);
        assertArrayEquals(new double[] {1.25, 0}, lens.compile(read).parameters());
        assertEquals(1.25, lens.compile(read).ior(), "phong refracts at the ior it reads");
        assertEquals("recipe.yaml:2:24: ior must lie between 0.1 and 100 (water is 1.33, glass 1.5, diamond 2.4), "
                        + "got 200",
                Recipes.error(registry, "materials:\n  m: {type: lens, ior: 200}\n"));
    }

    @Test
    void anObjectWithoutAMaterialGetsThePresetOfTheRegistrysFirstMaterialType() {
        String yaml = """
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1}
                """;
        Registry glowFirst = new Registry(Registry.STANDARD.shapes(), List.of(GlowType.TYPE),
                Registry.STANDARD.lights());
        assertEquals(GlowType.TYPE.preset(), Recipes.scene(glowFirst, yaml).objects().get(0).material());
        assertEquals(Registry.STANDARD.materials().get(0).preset(),
                Recipes.scene(REGISTRY, yaml).objects().get(0).material());
    }

    /**
     * A type reading keys of its own is sampled by the contract tests at the values it declares, every
     * combination over its preset; without them it has no sample, which fails
     * {@code BsdfContractTest} once the type is registered.
     */
    @Test
    void aTypeIsSampledAtTheValuesItDeclaresForItsOwnKeys() {
        MaterialType lens = new MaterialType("lens", new Dielectric(), new GlassResponse(), Vector3d.ONE, 0, 0, 1, 1)
                .reads("ior", 1.5, GlassType::ior)
                .reads("roughness", 0, MetalType::roughness)
                .compiledBy(m -> Dielectric.parameters(m.parameter("ior"), m.parameter("roughness")));
        assertEquals(List.of(), lens.samples());
        MaterialType sampled = lens.sampledAt("ior", 1.2, 2).sampledAt("roughness", 0, 0.5);
        assertEquals(List.of(new Material("lens", Vector3d.ONE, 0, 0, 1, 1, Map.of("ior", 1.2, "roughness", 0.0)),
                new Material("lens", Vector3d.ONE, 0, 0, 1, 1, Map.of("ior", 1.2, "roughness", 0.5)),
                new Material("lens", Vector3d.ONE, 0, 0, 1, 1, Map.of("ior", 2.0, "roughness", 0.0)),
                new Material("lens", Vector3d.ONE, 0, 0, 1, 1, Map.of("ior", 2.0, "roughness", 0.5))),
                sampled.samples());
        assertEquals(List.of(MatteType.TYPE.preset()), MatteType.TYPE.samples(),
                "a type without keys of its own: its preset");
        assertEquals(3, GlowType.TYPE.samples().size(), "the glow at each strength it declares");
        assertThrows(IllegalArgumentException.class, () -> GlowType.TYPE.sampledAt("ior", 1.5));
        assertThrows(IllegalArgumentException.class, () -> lens.sampledAt("kd", 0.5));
    }
}
