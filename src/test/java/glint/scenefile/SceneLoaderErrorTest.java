package glint.scenefile;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import glint.input.InputException;
import glint.registry.DirectionalLightType;
import glint.registry.LightType;
import glint.registry.MaterialType;
import glint.registry.Registry;
import glint.registry.ShapeType;
import glint.scene.Scene;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every error of docs/scene-format.md ("Errors"), with the exact message the user sees. Lines and
 * columns are counted by hand from the text blocks (the text starts on line 1, column 1 at the left
 * margin of the closing quotes).
 */
class SceneLoaderErrorTest {

    private static final String FILE = "scenes/x.yaml";

    private static InputException failure(String text) {
        return assertThrows(InputException.class, () -> SceneLoader.parse(FILE, text));
    }

    /** The type names the registry lists, in its order, as the messages list them. */
    private static final String OBJECT_TYPES = String.join(", ",
            Registry.STANDARD.shapes().stream().map(ShapeType::name).toList());
    private static final String LIGHT_TYPES = String.join(", ",
            Registry.STANDARD.lights().stream().map(LightType::name).toList());
    private static final String MATERIAL_TYPES = String.join(", ",
            Registry.STANDARD.materials().stream().map(MaterialType::name).toList());

    private static void assertError(String expected, String text) {
        assertEquals(expected, failure(text).getMessage());
    }

    // ---------------------------------------------------------------- unknown keys

    /** A merge key among the named materials is refused at the <<, never read as a material named <<. */
    @Test
    void aMergeKeyInMaterialsIsRefusedAtIt() {
        assertError("scenes/x.yaml:3:3: merge keys (<<) are not supported in materials; write the keys out (an alias "
                + "of a whole mapping, such as *name, works)", """
                materials:
                  blue: {type: matte, color: [0, 0, 1]}
                  <<: {red: {type: matte, color: [1, 0, 0]}}
                objects: [{type: sphere, center: [0, 1, 0], radius: 1, material: red}]
                """);
    }

    @Test
    void unknownKeyInSphereNamesLineColumnAndSuggestion() {
        String text = """
                # A scene with a typo in its last sphere.
                camera:
                  position: [0, 1, -5]
                  look_at: [0, 1, 0]
                lights:
                  - {type: point, position: [-5, 8, -6], intensity: 100}
                objects:
                  - type: sphere
                    center: [-2, 1, 0]
                    radius: 1
                  - type: sphere
                    radus: 1
                    center: [2, 1, 0]
                """;
        InputException e = failure(text);
        assertEquals("scenes/x.yaml:12:5: unknown key 'radus' in sphere (did you mean 'radius'?)", e.getMessage());
        assertAll(
                () -> assertEquals(FILE, e.file()),
                () -> assertEquals(12, e.line()),
                () -> assertEquals(5, e.column()),
                () -> assertEquals("unknown key 'radus' in sphere (did you mean 'radius'?)", e.problem()));
    }

    @Test
    void unknownTopLevelKey() {
        assertError("scenes/x.yaml:3:1: unknown key 'objets' in the scene (did you mean 'objects'?)", """
                camera:
                  fov: 60
                objets:
                  - {type: sphere, center: [0, 0, 0], radius: 1}
                """);
    }

    @Test
    void unknownTopLevelKeyFarFromAnyListsTheKnownOnes() {
        assertError("scenes/x.yaml:1:1: unknown key 'spheres' in the scene (expected one of: "
                + "camera, background, ambient, lights, materials, objects, views, render)", """
                spheres: []
                """);
    }

    @Test
    void unknownKeyInCamera() {
        assertError("scenes/x.yaml:3:3: unknown key 'fvo' in camera (did you mean 'fov'?)", """
                camera:
                  position: [0, 1, -5]
                  fvo: 60
                """);
    }

    @Test
    void unknownKeyInPlane() {
        // "  - {" is columns 1-5, "type: plane, " 6-18, "point: [0, 0, 0], " 19-36, so "normall" is at 37
        assertError("scenes/x.yaml:2:37: unknown key 'normall' in plane (did you mean 'normal'?)", """
                objects:
                  - {type: plane, point: [0, 0, 0], normall: [0, 1, 0]}
                """);
    }

    @Test
    void unknownKeyInPointLight() {
        // "  - {" 1-5, "type: point, " 6-18, "position: [0, 5, 0], " 19-39, "intensty" at 40
        assertError("scenes/x.yaml:2:40: unknown key 'intensty' in point light (did you mean 'intensity'?)", """
                lights:
                  - {type: point, position: [0, 5, 0], intensty: 10}
                """);
    }

    @Test
    void pointLightKeyInDirectionalLight() {
        assertError("scenes/x.yaml:4:5: unknown key 'position' in directional light "
                + "(expected one of: type, " + String.join(", ", DirectionalLightType.TYPE.keys()) + ", color, intensity)",
                """
                lights:
                  - type: directional
                    direction: [0, -1, 0]
                    position: [0, 5, 0]
                """);
    }

    @Test
    void unknownKeyInInlineMaterial() {
        // line 2: "  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: metal, " is 73 characters
        assertError("scenes/x.yaml:2:74: unknown key 'roughnes' in material (did you mean 'roughness'?)", """
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: metal, roughnes: 0.1}}
                """);
    }

    @Test
    void unknownKeyInNamedMaterial() {
        // "  gold: {" 1-9, "type: metal, " 10-22, "colour" at 23
        assertError("scenes/x.yaml:2:23: unknown key 'colour' in material 'gold' (did you mean 'color'?)", """
                materials:
                  gold: {type: metal, colour: [1, 0.8, 0.3]}
                """);
    }

    @Test
    void aKeyOfAnotherMaterialTypeNamesTheTypeThatReadsItAndTheFix() {
        // "  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: matte, " is 73 characters:
        // "ior" at 74, the first of the keys a matte material does not read, in the order written
        assertError("scenes/x.yaml:2:74: a matte material has no ior (ior is a key of glass; write type: glass, "
                + "or remove ior)", """
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: matte, ior: 7, roughness: 0.9, kt: 3}}
                """);
        // "  gold: {" 1-9, "type: metal, " 10-22, "ior" at 23
        assertError("scenes/x.yaml:2:23: a metal material has no ior (ior is a key of glass; write type: glass, "
                + "or remove ior)", """
                materials:
                  gold: {type: metal, ior: 1.5}
                """);
        // "  pane: {" 1-9, "kt: 0.5, " 10-18, "ior" at 19: before the type, still the metal's key check
        assertError("scenes/x.yaml:2:19: a metal material has no ior (ior is a key of glass; write type: glass, "
                + "or remove ior)", """
                materials:
                  pane: {kt: 0.5, ior: 1.2, type: metal}
                """);
        // roughness is read by two types: both are named
        assertError("scenes/x.yaml:2:20: a matte material has no roughness (roughness is a key of metal and glass; "
                + "write type: metal or type: glass, or remove roughness)", """
                materials:
                  m: {type: matte, roughness: 0.2}
                """);
    }

    @Test
    void followingTheFixOfAKeyOfAnotherTypeLoads() throws InputException {
        Scene scene = SceneLoader.parse(FILE, """
                materials:
                  m: {type: metal, roughness: 0.5}
                  n: {type: matte}
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: m}
                  - {type: sphere, center: [0, 0, 3], radius: 1, material: n}
                """);
        assertEquals(0.5, scene.objects().get(0).material().parameter("roughness"));
        assertEquals(java.util.Map.of(), scene.objects().get(1).material().parameters());
    }

    @Test
    void aKeyOfAnotherMaterialTypeIsCheckedBeforeItsValue() {
        // a matte material's roughness is refused as a key, not as a value out of [0, 1]
        assertError("scenes/x.yaml:2:20: a matte material has no roughness (roughness is a key of metal and glass; "
                + "write type: metal or type: glass, or remove roughness)", """
                materials:
                  m: {type: matte, roughness: 7}
                """);
    }

    @Test
    void aMisspeltKeyOfTheTypeGetsTheTypesOwnKeyAsHint() {
        // "  m: {type: metal, " is 19 characters
        assertError("scenes/x.yaml:2:20: unknown key 'rougness' in material 'm' (did you mean 'roughness'?)", """
                materials:
                  m: {type: metal, rougness: 0.5}
                """);
        assertError("scenes/x.yaml:2:20: unknown key 'ior2' in material 'm' (did you mean 'ior'?)", """
                materials:
                  m: {type: glass, ior2: 1}
                """);
        assertError("scenes/x.yaml:2:20: unknown key 'shinyness' in material 'm' (did you mean 'shininess'?)", """
                materials:
                  m: {type: matte, shinyness: 1}
                """);
    }

    @Test
    void aMisspeltKeyOfAnotherTypeGetsNoHintTowardsAKeyTheTypeRefuses() {
        // roughness is metal's: a matte material lists its own keys, which do not have it
        assertError("scenes/x.yaml:2:20: unknown key 'rougness' in material 'm' (expected one of: type, color, kd, ks,"
                + " kt, shininess)", """
                materials:
                  m: {type: matte, rougness: 0.5}
                """);
        assertError("scenes/x.yaml:2:20: unknown key 'ior2' in material 'm' (expected one of: type, color, kd, ks, kt,"
                + " shininess, roughness)", """
                materials:
                  m: {type: metal, ior2: 1}
                """);
    }

    @Test
    void aKeyNoMaterialTypeReadsListsTheKeysOfItsType() {
        assertError("scenes/x.yaml:2:20: unknown key 'albedo' in material 'm' (expected one of: type, color, kd, ks, kt,"
                + " shininess)", """
                materials:
                  m: {type: matte, albedo: [1, 1, 1]}
                """);
        assertError("scenes/x.yaml:2:20: unknown key 'albedo' in material 'm' (expected one of: type, color, kd, ks, kt,"
                + " shininess, ior, roughness)", """
                materials:
                  m: {type: glass, albedo: [1, 1, 1]}
                """);
    }

    @Test
    void aMaterialsTypeIsCheckedBeforeItsKeys() {
        // "  m: {rougness: 0.5, type: " is 27 characters: the unknown type, not the key before it
        assertError("scenes/x.yaml:2:28: unknown material type 'metl' (did you mean 'metal'?)", """
                materials:
                  m: {rougness: 0.5, type: metl}
                """);
        assertError("scenes/x.yaml:2:6: missing required key 'type' in material 'm' (one of: " + MATERIAL_TYPES + ")", """
                materials:
                  m: {colr: [1, 0, 0]}
                """);
    }

    // ---------------------------------------------------------------- unknown types and names

    @Test
    void unknownObjectTypeWithSuggestion() {
        // "  - {type: " is columns 1-11, the value "sphre" starts at 12
        assertError("scenes/x.yaml:2:12: unknown object type 'sphre' (did you mean 'sphere'?)", """
                objects:
                  - {type: sphre, center: [0, 0, 0], radius: 1}
                """);
    }

    @Test
    void unknownObjectTypeFarFromAnyListsTheTypes() {
        assertError("scenes/x.yaml:2:11: unknown object type 'cube' (expected one of: " + OBJECT_TYPES + ")", """
                objects:
                  - type: cube
                    size: 1
                """);
    }

    @Test
    void unknownLightType() {
        assertError("scenes/x.yaml:2:12: unknown light type 'spot' (expected one of: " + LIGHT_TYPES + ")", """
                lights:
                  - {type: spot, position: [0, 5, 0]}
                """);
    }

    @Test
    void unknownLightTypeWithSuggestion() {
        assertError("scenes/x.yaml:2:12: unknown light type 'directonal' (did you mean 'directional'?)", """
                lights:
                  - {type: directonal, direction: [0, -1, 0]}
                """);
    }

    @Test
    void unknownMaterialType() {
        // "  shiny: {type: " is 16 characters
        assertError("scenes/x.yaml:2:17: unknown material type 'metall' (did you mean 'metal'?)", """
                materials:
                  shiny: {type: metall}
                """);
    }

    @Test
    void unknownMaterialNameSuggestsANamedMaterial() {
        // line 4: "  - {type: sphere, center: [0, 0, 0], radius: 1, material: " is 59 characters
        assertError("scenes/x.yaml:4:60: unknown material 'gld' (did you mean 'gold'?)", """
                materials:
                  gold: {type: metal, color: [1.0, 0.77, 0.34]}
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: gld}
                """);
    }

    @Test
    void unknownMaterialNameSuggestsAPreset() {
        assertError("scenes/x.yaml:5:15: unknown material 'glas' (did you mean 'glass'?)", """
                objects:
                  - type: sphere
                    center: [0, 0, 0]
                    radius: 1
                    material: glas
                """);
    }

    @Test
    void unknownMaterialNameFarFromAnyListsPresetsThenNamedInOrder() {
        assertError("scenes/x.yaml:6:15: unknown material 'blue' (expected one of: " + MATERIAL_TYPES + ", red, "
                + "gold)", """
                materials:
                  red: {type: matte, color: [0.8, 0.1, 0.1]}
                  gold: {type: metal, color: [1.0, 0.77, 0.34]}
                objects:
                  - type: plane
                    material: blue
                    point: [0, 0, 0]
                    normal: [0, 1, 0]
                """);
    }

    @Test
    void materialNameRedefiningAPreset() {
        assertError("scenes/x.yaml:3:3: material name 'glass' is a preset and cannot be redefined "
                + "(choose another name)", """
                materials:
                  red: {type: matte, color: [0.8, 0.1, 0.1]}
                  glass: {type: glass, ior: 1.33}
                """);
    }

    @Test
    void duplicateMaterialName() {
        assertError("scenes/x.yaml:3:3: duplicate material name 'red'", """
                materials:
                  red: {type: matte, color: [0.8, 0.1, 0.1]}
                  red: {type: matte, color: [0.9, 0.1, 0.1]}
                """);
    }

    // ---------------------------------------------------------------- missing required keys

    @Test
    void missingRadiusPointsAtTheSphere() {
        assertError("scenes/x.yaml:2:5: missing required key 'radius' in sphere", """
                objects:
                  - {type: sphere, center: [0, 0, 0]}
                """);
    }

    @Test
    void missingCenter() {
        assertError("scenes/x.yaml:3:5: missing required key 'center' in sphere", """
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                  - type: sphere
                    radius: 1
                """);
    }

    @Test
    void missingNormal() {
        assertError("scenes/x.yaml:2:5: missing required key 'normal' in plane", """
                objects:
                  - type: plane
                    point: [0, 0, 0]
                """);
    }

    @Test
    void missingPoint() {
        assertError("scenes/x.yaml:2:5: missing required key 'point' in plane", """
                objects:
                  - {type: plane, normal: [0, 1, 0]}
                """);
    }

    @Test
    void missingPosition() {
        assertError("scenes/x.yaml:2:5: missing required key 'position' in point light", """
                lights:
                  - {type: point, intensity: 10}
                """);
    }

    @Test
    void missingDirection() {
        assertError("scenes/x.yaml:2:5: missing required key 'direction' in directional light", """
                lights:
                  - {type: directional, color: [1, 1, 1]}
                """);
    }

    @Test
    void missingObjectType() {
        assertError("scenes/x.yaml:2:5: missing required key 'type' in object (one of: " + OBJECT_TYPES + ")", """
                objects:
                  - {center: [0, 0, 0], radius: 1}
                """);
    }

    @Test
    void missingLightType() {
        assertError("scenes/x.yaml:2:5: missing required key 'type' in light (one of: " + LIGHT_TYPES + ")", """
                lights:
                  - position: [0, 5, 0]
                """);
    }

    @Test
    void missingMaterialType() {
        assertError("scenes/x.yaml:2:8: missing required key 'type' in material 'red' (one of: " + MATERIAL_TYPES + ")",
                """
                materials:
                  red: {color: [0.8, 0.1, 0.1]}
                """);
    }

    @Test
    void missingInlineMaterialType() {
        assertError("scenes/x.yaml:5:15: missing required key 'type' in material (one of: " + MATERIAL_TYPES + ")",
                """
                objects:
                  - type: sphere
                    center: [0, 0, 0]
                    radius: 1
                    material: {color: [1, 0, 0]}
                """);
    }

    // ---------------------------------------------------------------- values out of range

    @Test
    void radiusZero() {
        assertError("scenes/x.yaml:4:13: radius must be > 0, got 0", """
                objects:
                  - type: sphere
                    center: [0, 0, 0]
                    radius: 0
                """);
    }

    @Test
    void radiusWhoseSquareUnderflows() {
        assertError("scenes/x.yaml:2:47: radius must lie between 1e-150 and 1e150 (its square must be a normal"
                + " double), got 1e-200", """
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1e-200}
                """);
    }

    @Test
    void radiusWhoseSquareOverflows() {
        assertError("scenes/x.yaml:2:47: radius must lie between 1e-150 and 1e150 (its square must be a normal"
                + " double), got 3e200", """
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 3e200}
                """);
    }

    @Test
    void radiusNegative() {
        // "  - {type: sphere, center: [0, 0, 0], radius: " is 46 characters
        assertError("scenes/x.yaml:2:47: radius must be > 0, got -1.5", """
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: -1.5}
                """);
    }

    @Test
    void iorZero() {
        // "  clear: {type: glass, ior: " is 28 characters
        assertError("scenes/x.yaml:2:29: ior must be > 0, got 0", """
                materials:
                  clear: {type: glass, ior: 0}
                """);
    }

    @Test
    void iorNegative() {
        assertError("scenes/x.yaml:2:29: ior must be > 0, got -1.5", """
                materials:
                  clear: {type: glass, ior: -1.5}
                """);
    }

    @Test
    void negativeIntensity() {
        assertError("scenes/x.yaml:4:16: intensity must be >= 0, got -5", """
                lights:
                  - type: point
                    position: [0, 5, 0]
                    intensity: -5
                """);
    }

    @Test
    void zeroNormal() {
        // "  - {type: plane, point: [0, 0, 0], normal: " is 44 characters
        assertError("scenes/x.yaml:2:45: normal must not be the zero vector", """
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 0, 0]}
                """);
    }

    @Test
    void zeroDirection() {
        assertError("scenes/x.yaml:3:16: direction must not be the zero vector", """
                lights:
                  - type: directional
                    direction: [0, 0.0, 0]
                """);
    }

    @Test
    void fovZero() {
        assertError("scenes/x.yaml:2:8: fov must lie strictly between 0 and 180 degrees, got 0", """
                camera:
                  fov: 0
                """);
    }

    @Test
    void fov180() {
        assertError("scenes/x.yaml:3:8: fov must lie strictly between 0 and 180 degrees, got 180", """
                camera:
                  position: [0, 1, -5]
                  fov: 180
                """);
    }

    @Test
    void glassRoughnessOutOfRange() {
        // "  frost: {type: glass, " is 23 characters: roughness at 24, its value at 35
        assertError("scenes/x.yaml:2:35: roughness must lie in [0, 1], got 1.5", """
                materials:
                  frost: {type: glass, roughness: 1.5}
                """);
        assertError("scenes/x.yaml:2:35: roughness must lie in [0, 1], got -0.25", """
                materials:
                  frost: {type: glass, roughness: -0.25, ior: 1.5}
                """);
    }

    @Test
    void negativeAperture() {
        assertError("scenes/x.yaml:2:13: aperture must be >= 0, got -0.1", """
                camera:
                  aperture: -0.1
                """);
    }

    @Test
    void apertureBeyondTheLongestLength() {
        assertError("scenes/x.yaml:2:13: aperture must be at most 1e150, got 2e150", """
                camera:
                  aperture: 2e150
                """);
    }

    @Test
    void nonFiniteApertureAndFocus() {
        assertError("scenes/x.yaml:2:13: expected a finite number for aperture, got '.inf'", """
                camera:
                  aperture: .inf
                """);
        assertError("scenes/x.yaml:2:10: expected a finite number for focus, got '.nan'", """
                camera:
                  focus: .nan
                """);
    }

    @Test
    void focusZeroOrNegative() {
        assertError("scenes/x.yaml:3:10: focus must be > 0, got 0", """
                camera:
                  aperture: 0.1
                  focus: 0
                """);
        assertError("scenes/x.yaml:2:10: focus must be > 0, got -2", """
                camera:
                  focus: -2
                """);
    }

    @Test
    void focusOutsideTheLengthsASceneMayHave() {
        assertError("scenes/x.yaml:2:10: focus must lie between 1e-150 and 1e150 (its square must be a normal"
                + " double), got 1e-200", """
                camera:
                  focus: 1e-200
                """);
    }

    @Test
    void aViewsLensIsCheckedAsTheCamerasIs() {
        assertError("scenes/x.yaml:2:50: aperture must be >= 0, got -1", """
                views:
                  - {name: near, position: [0, 1, -5], aperture: -1}
                """);
        assertError("scenes/x.yaml:2:25: focus must be > 0, got 0", """
                views:
                  - {name: near, focus: 0}
                """);
    }

    @Test
    void negativeRoughness() {
        assertError("scenes/x.yaml:2:52: roughness must lie in [0, 1], got -0.1", """
                materials:
                  gold: {type: metal, color: [1, 1, 1], roughness: -0.1}
                """);
    }

    @Test
    void negativeLightRadius() {
        assertError("scenes/x.yaml:2:48: radius must be >= 0 (0 is a point light), got -0.5", """
                lights:
                  - {type: point, position: [0, 5, 0], radius: -0.5}
                """);
    }

    @Test
    void lightRadiusTooSmallForItsRadiance() {
        assertError("scenes/x.yaml:2:48: radius must be 0 (a point light) or between 1e-50 and 1e50, got 1e-60", """
                lights:
                  - {type: point, position: [0, 5, 0], radius: 1e-60}
                """);
    }

    @Test
    void negativeSunAngle() {
        assertError("scenes/x.yaml:2:55: angle must lie in [0, 180) degrees (the disc's apparent diameter; the sun's"
                + " is 0.53), got -1", """
                lights:
                  - {type: directional, direction: [0, -1, 0], angle: -1}
                """);
    }

    @Test
    void sunAngleOf180() {
        assertError("scenes/x.yaml:2:55: angle must lie in [0, 180) degrees (the disc's apparent diameter; the sun's"
                + " is 0.53), got 180", """
                lights:
                  - {type: directional, direction: [0, -1, 0], angle: 180}
                """);
    }

    @Test
    void negativeCoefficient() {
        assertError("scenes/x.yaml:2:24: kd must be >= 0, got -1", """
                materials:
                  m: {type: matte, kd: -1}
                """);
    }

    // ---------------------------------------------------------------- values too large to mean anything

    @Test
    void aMaterialColourAbove1e30IsRefused() {
        // "  m: {type: metal, color: " is 26 characters
        assertError("scenes/x.yaml:2:27: color must be at most 1e30 in each component, got 1.00e+300 (a material's "
                + "color is the share of the light it sends back, 1 for all of it)", """
                materials:
                  m: {type: metal, color: [0, 1e300, 0]}
                """);
    }

    @Test
    void aMaterialsColourIsBoundedAsEveryColourAndLightOfAScene() {
        assertEquals(SceneLoader.MAX_RADIANCE, MaterialType.MAX_SHARE);
    }

    @Test
    void aMaterialColourOf1e30IsAllowed() throws InputException {
        Scene scene = SceneLoader.parse(FILE, """
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: matte, color: [1e30, 0, 1e30]}}
                """);
        assertEquals(1e30, scene.objects().get(0).material().color().x());
    }

    @Test
    void phongCoefficientsAbove1e30AreRefused() {
        // "  m: {type: matte, kt: " is 23 characters
        assertError("scenes/x.yaml:2:24: kt must be at most 1e30, got 2e30 (the share of the light it sends back, 1 for "
                + "all of it)", """
                materials:
                  m: {type: matte, kt: 2e30}
                """);
        assertError("scenes/x.yaml:2:24: kd must be at most 1e30, got 1.0000001e30 (the share of the light it sends "
                + "back, 1 for all of it)", """
                materials:
                  m: {type: matte, kd: 1.0000001e30}
                """);
    }

    @Test
    void aShininessAbove1e6IsRefused() {
        assertError("scenes/x.yaml:2:31: shininess must be at most 1e6, got 1000001 (the highlight's exponent: 10 "
                + "is broad, 1000 a point)", """
                materials:
                  m: {type: metal, shininess: 1000001}
                """);
    }

    @Test
    void anIorOutsideATenthToAHundredIsRefused() {
        assertError("scenes/x.yaml:2:29: ior must lie between 0.1 and 100 (water is 1.33, glass 1.5, diamond 2.4), "
                + "got 0.05", """
                materials:
                  clear: {type: glass, ior: 0.05}
                """);
        assertError("scenes/x.yaml:2:29: ior must lie between 0.1 and 100 (water is 1.33, glass 1.5, diamond 2.4), "
                + "got 101", """
                materials:
                  clear: {type: glass, ior: 101}
                """);
    }

    @Test
    void aBackgroundJustAboveTheLimitShowsTheDifference() {
        // %.3g would print 1.00e+30, the limit itself
        assertError("scenes/x.yaml:1:13: background must be at most 1e30 in each component, got 1.000001e+30 "
                + "(the image stores radiance as float, up to 3.4e38)", """
                background: [0, 1.000001e30, 0]
                """);
    }

    @Test
    void aCameraJustFartherThanTheLimitShowsTheDifference() {
        // "  look_at: " is 11 characters; %.2g would print 1.0e+150, the limit itself
        assertError("scenes/x.yaml:3:12: look_at is 1.01e+150 from the camera position; it must be between 1e-150 "
                + "and 1e150 away", """
                camera:
                  position: [0, 0, 0]
                  look_at: [0, 0, 1.01e150]
                """);
    }

    // ---------------------------------------------------------------- what is echoed, cut

    @Test
    void aNumberThousandsOfDigitsLongIsCutInTheMessage() {
        String digits = "1" + "0".repeat(200) + "." + "0".repeat(5000); // 1e200
        InputException e = failure("objects:\n  - {type: sphere, center: [0, 0, 0], radius: " + digits + "}\n");
        assertEquals("scenes/x.yaml:2:47: radius must lie between 1e-150 and 1e150 (its square must be a normal double), "
                + "got " + digits.substring(0, 60) + "...", e.getMessage());
    }

    @Test
    void anUndefinedAliasOfAThousandCharactersIsCutInTheMessage() {
        String name = "a".repeat(1000);
        assertError("scenes/x.yaml:1:11: YAML syntax error: found undefined alias " + "a".repeat(60) + "...",
                "objects: [*" + name + "]\n");
    }

    // ---------------------------------------------------------------- merge keys and aliases

    @Test
    void aMergeKeyInAnObjectWithoutATypeIsAMergeKeyError() {
        // the type would come from the merged mapping: the merge key is what is wrong
        assertError("scenes/x.yaml:3:6: merge keys (<<) are not supported in object; write the keys out (an alias "
                + "of a whole mapping, such as *name, works)", """
                objects:
                  - &ball {type: sphere, center: [0, 1, 0], radius: 1}
                  - {<<: *ball, center: [2, 1, 0]}
                """);
    }

    @Test
    void aMergeKeyInALightWithATypeIsAMergeKeyErrorOfItsType() {
        // "  - {type: point, " is 18 characters
        assertError("scenes/x.yaml:3:19: merge keys (<<) are not supported in point light; write the keys out (an "
                + "alias of a whole mapping, such as *name, works)", """
                lights:
                  - &lamp {type: point, position: [0, 5, 0]}
                  - {type: point, <<: *lamp}
                """);
    }

    @Test
    void theAliasBeyondFiftyIsReportedWhereItStands() {
        StringBuilder text = new StringBuilder("objects:\n  - {type: sphere, center: &c [0, 0, 0], radius: 1}\n");
        for (int i = 0; i < 60; i++) {
            text.append("  - {type: sphere, center: *c, radius: 1}\n");
        }
        // aliases 1 to 50 on lines 3 to 52; the 51st on line 53, after "  - {type: sphere, center: " (27 characters)
        assertError("scenes/x.yaml:53:28: YAML error: more than 50 aliases of lists or mappings (an alias bomb?); "
                + "write the values out", text.toString());
    }

    @Test
    void aliasesOfNumbersAreNotCounted() throws InputException {
        StringBuilder text = new StringBuilder("objects:\n  - {type: sphere, center: [0, 0, 0], radius: &r 1}\n");
        for (int i = 0; i < 60; i++) {
            text.append("  - {type: sphere, center: [").append(i).append(", 0, 0], radius: *r}\n");
        }
        assertEquals(61, SceneLoader.parse(FILE, text.toString()).objects().size());
    }

    // ---------------------------------------------------------------- characters, not UTF-16 units

    @Test
    void columnsCountCharactersNotUtf16Units() {
        // two emoji (each two UTF-16 units) before the bad value: "  😀😀: {type: matte, kd: " is 24 characters
        assertError("scenes/x.yaml:2:25: kd must be >= 0, got -1", """
                materials:
                  😀😀: {type: matte, kd: -1}
                """);
    }

    @Test
    void aCommentOf40001EmojiIsALineOf40001Characters() throws InputException {
        // 80,004 UTF-16 units, under the limit of 65,536 characters
        SceneLoader.parse(FILE, "# " + "😀".repeat(40_001) + "\nobjects: []\n");
        InputException e = failure("objects: []\n# " + "😀".repeat(65_535) + "\n");
        assertEquals("scenes/x.yaml:2:65537: line 2 is 65,537 characters long; the longest line accepted is 65,536 "
                + "(break it into shorter lines)", e.getMessage());
    }

    @Test
    void negativeColorComponent() {
        assertError("scenes/x.yaml:1:13: background must not have negative components, got [0.0, -0.1, 0.0]",
                """
                background: [0, -0.1, 0]
                """);
    }

    @Test
    void lookAtEqualToPosition() {
        assertError("scenes/x.yaml:3:12: look_at must differ from the camera position", """
                camera:
                  position: [1, 2, 3]
                  look_at: [1, 2, 3]
                """);
    }

    @Test
    void upParallelToTheViewingDirection() {
        assertError("scenes/x.yaml:4:7: up must not be zero or parallel to the viewing direction "
                + "(look_at - position)", """
                camera:
                  position: [0, 0, 0]
                  look_at: [0, 5, 0]
                  up: [0, 1, 0]
                """);
    }

    // ---------------------------------------------------------------- numbers and vectors

    @Test
    void infinity() {
        assertError("scenes/x.yaml:2:47: expected a finite number for radius, got '.inf'", """
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: .inf}
                """);
    }

    @Test
    void negativeInfinity() {
        assertError("scenes/x.yaml:2:17: expected a finite number for intensity, got '-.Inf'", """
                lights:
                  - {intensity: -.Inf, type: point, position: [0, 1, 0]}
                """);
    }

    @Test
    void notANumber() {
        // "  - {type: sphere, center: [0, " is 31 characters
        assertError("scenes/x.yaml:2:32: expected a finite number for center, got '.nan'", """
                objects:
                  - {type: sphere, center: [0, .nan, 0], radius: 1}
                """);
    }

    @Test
    void numberTooLargeForADouble() {
        assertError("scenes/x.yaml:2:8: expected a finite number for fov, got '1e999' (too large)", """
                camera:
                  fov: 1e999
                """);
    }

    @Test
    void stringWhereANumberIsExpected() {
        assertError("scenes/x.yaml:4:13: expected a number for radius, got 'big'", """
                objects:
                  - type: sphere
                    center: [0, 0, 0]
                    radius: big
                """);
    }

    @Test
    void nothingWhereANumberIsExpected() {
        assertError("scenes/x.yaml:2:7: expected a number for fov, got nothing", """
                camera:
                  fov:
                  position: [0, 1, -5]
                """);
    }

    @Test
    void quotedNumber() {
        // the message points at the opening quote
        assertError("scenes/x.yaml:4:13: expected a number for radius, got the quoted string '1'", """
                objects:
                  - type: sphere
                    center: [0, 0, 0]
                    radius: "1"
                """);
    }

    @Test
    void quotedNumberInAVector() {
        assertError("scenes/x.yaml:2:20: expected a number for position, got the quoted string '-5'", """
                camera:
                  position: [0, 1, '-5']
                """);
    }

    @Test
    void twoElementVector() {
        assertError("scenes/x.yaml:3:13: expected a list of 3 numbers for center, got 2 elements", """
                objects:
                  - type: sphere
                    center: [0, 1]
                    radius: 1
                """);
    }

    @Test
    void scalarWhereAVectorIsExpected() {
        assertError("scenes/x.yaml:1:10: expected a list of 3 numbers for ambient like [0, 1, 0], got '0.1'", """
                ambient: 0.1
                """);
    }

    // ---------------------------------------------------------------- structure

    @Test
    void duplicateKeyPointsAtTheSecondOne() {
        assertError("scenes/x.yaml:5:5: duplicate key 'radius' in sphere", """
                objects:
                  - type: sphere
                    center: [0, 0, 0]
                    radius: 1
                    radius: 2
                """);
    }

    @Test
    void duplicateTopLevelKey() {
        assertError("scenes/x.yaml:3:1: duplicate key 'camera' in the scene", """
                camera: {fov: 60}
                objects: []
                camera: {fov: 70}
                """);
    }

    @Test
    void anUnclosedListIsReportedWhereItOpens() {
        // the unclosed "[" at column 28 meets "}" at column 47
        assertError("scenes/x.yaml:2:28: this list, opened with '[', is not closed: add the ']' that ends it "
                + "(at line 2, column 47 it was still open and '}' came instead of ',' or ']')", """
                objects:
                  - {type: sphere, center: [0, 1, 0, radius: 1}
                """);
    }

    /** A list left open at the end of a line: the parser finds out on a later line; the error points at the list. */
    @Test
    void aListLeftOpenAtTheEndOfItsLineIsReportedOnThatLine() {
        assertError("scenes/x.yaml:8:13: this list, opened with '[', is not closed: add the ']' that ends it "
                + "(at line 9, column 10 it was still open and ':' came instead of ',' or ']')", """
                lights:
                  - {type: point, position: [-5, 8, -6], intensity: 100}
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 1}
                  - {type: sphere, center: [2, 1, 0], radius: 1}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                camera:
                  position: [0, 1, -5
                  look_at: [0, 1, 0]
                """);
        assertError("scenes/x.yaml:1:9: this mapping, opened with '{', is not closed: add the '}' that ends it "
                + "(at line 2, column 1 it was still open and other text came instead of ',' or '}')", """
                camera: {position: [0, 1, -5]
                objects: []
                """);
    }

    @Test
    void yamlSyntaxErrorHasAPosition() {
        assertError("scenes/x.yaml:1:11: YAML syntax error: mapping values are not allowed here", """
                objects: a: b
                """);
    }

    @Test
    void badIndentationSaysSo() {
        assertError("scenes/x.yaml:3:2: YAML syntax error: expected <block end>, but found "
                + "'<block mapping start>' (while parsing a block mapping); check the indentation", """
                camera:
                  position: [0, 1, -5]
                 fov: 60
                """);
    }

    @Test
    void tabIndentation() {
        InputException e = failure("camera:\n\tfov: 60\n");
        assertEquals(2, e.line());
        assertEquals(1, e.column());
        assertEquals("scenes/x.yaml:2:1: YAML syntax error: found character '\\t(TAB)' that cannot start any "
                + "token. (Do not use \\t(TAB) for indentation) (while scanning for the next token)", e.getMessage());
    }

    @Test
    void emptyFile() {
        assertError("scenes/x.yaml:1:1: the scene is empty (expected a mapping with keys such as camera, lights, "
                + "objects)", "");
    }

    @Test
    void fileWithOnlyCommentsIsEmpty() {
        assertError("scenes/x.yaml:1:1: the scene is empty (expected a mapping with keys such as camera, lights, "
                + "objects)", """
                # nothing here yet

                """);
    }

    @Test
    void listAtTheTop() {
        assertError("scenes/x.yaml:1:1: expected a mapping for the scene, got a list", """
                - {type: sphere, center: [0, 0, 0], radius: 1}
                """);
    }

    @Test
    void objectsNotAList() {
        assertError("scenes/x.yaml:2:3: expected a list of objects, got a mapping", """
                objects:
                  type: sphere
                """);
    }

    @Test
    void objectNotAMapping() {
        assertError("scenes/x.yaml:2:5: expected a mapping for object, got 'sphere'", """
                objects:
                  - sphere
                """);
    }

    @Test
    void emptyMaterialValue() {
        assertError("scenes/x.yaml:2:59: expected a mapping for material, got nothing", """
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: }
                """);
    }

    // ---------------------------------------------------------------- files

    @Test
    void missingFile(@TempDir Path dir) {
        Path path = dir.resolve("nope.yaml");
        InputException e = assertThrows(InputException.class, () -> SceneLoader.load(path));
        assertEquals(path + ": no such file", e.getMessage());
        assertEquals(0, e.line());
    }

    @Test
    void binaryFile(@TempDir Path dir) throws IOException {
        Path path = dir.resolve("image.yaml");
        Files.write(path, new byte[] {(byte) 0x89, 'P', 'N', 'G', (byte) 0xff, (byte) 0xfe});
        InputException e = assertThrows(InputException.class, () -> SceneLoader.load(path));
        // 0x89 cannot start a UTF-8 character: the first byte, line 1, column 1
        assertEquals(path + ":1:1: not UTF-8 text: byte 0x89 cannot stand here in UTF-8 (save the file as UTF-8)",
                e.getMessage());
    }

    @Test
    void loadNamesTheFileByItsPath(@TempDir Path dir) throws IOException {
        Path path = dir.resolve("typo.yaml");
        Files.writeString(path, "camera:\n  fvo: 60\n");
        InputException e = assertThrows(InputException.class, () -> SceneLoader.load(path));
        assertEquals(path + ":2:3: unknown key 'fvo' in camera (did you mean 'fov'?)", e.getMessage());
    }
}
