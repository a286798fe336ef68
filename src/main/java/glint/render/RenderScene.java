package glint.render;

import glint.config.Shading;
import glint.accel.Aggregate;
import glint.accel.AggregatePolicy;
import glint.geometry.PlaneKind;
import glint.geometry.Primitives;
import glint.geometry.PrimitiveKind;
import glint.geometry.SphereKind;
import glint.scene.Camera;
import glint.scene.Material;
import glint.scene.MaterialType;
import glint.scene.Plane;
import glint.scene.Scene;
import glint.scene.SceneObject;
import glint.scene.Sphere;
import glint.shading.Lights;
import glint.shading.Materials;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * A scene compiled for tracing: its primitives by kind in flat arrays and the aggregate that
 * searches them, materials and lights in flat arrays, the camera as a basis, and the settings.
 * Immutable; shared by all render threads.
 */
public final class RenderScene {

    final RenderSettings settings;
    final Primitives primitives;
    final Aggregate aggregate;
    /**
     * Per light: the aggregate its shadow rays ask ({@link AggregatePolicy#forPointLight} for a
     * point light when the policy chose the scene's aggregate; the scene's aggregate otherwise).
     */
    final Aggregate[] shadowAggregate;
    /** Per primitive: its material's number. */
    final int[] materialOf;
    final Materials materials;
    final Lights lights;
    /**
     * Per primitive: the fraction of light a shadow ray passes through it. The cook-torrance model
     * passes none; the phong model passes kt through glass.
     */
    final double[] shadowPass;
    final double backgroundR, backgroundG, backgroundB;
    final double ambientR, ambientG, ambientB;
    /** The camera, world space. */
    final CameraBasis camera;

    private RenderScene(Scene scene, RenderSettings settings, Function<Primitives, Aggregate> aggregateOf,
                        boolean lightCells) {
        this.settings = settings;
        List<Material> materialList = new ArrayList<>();
        List<SceneObject> spheres = new ArrayList<>(), planes = new ArrayList<>();
        for (SceneObject o : scene.objects()) {
            (o.shape() instanceof Sphere ? spheres : o.shape() instanceof Plane ? planes : unknownKind(o)).add(o);
        }
        double[] sphereData = new double[4 * spheres.size()];
        for (int i = 0; i < spheres.size(); i++) {
            Sphere s = (Sphere) spheres.get(i).shape();
            put4(sphereData, i, s.center().x(), s.center().y(), s.center().z(), s.radius());
        }
        double[] planeData = new double[4 * planes.size()];
        for (int i = 0; i < planes.size(); i++) {
            Plane p = (Plane) planes.get(i).shape();
            put4(planeData, i, p.normal().x(), p.normal().y(), p.normal().z(), p.normal().dot(p.point()));
        }
        List<PrimitiveKind> kinds = List.of(new SphereKind(sphereData), new PlaneKind(planeData));
        primitives = new Primitives(kinds);
        aggregate = aggregateOf.apply(primitives);
        List<SceneObject> inOrder = new ArrayList<>(spheres);
        inOrder.addAll(planes);
        materialOf = new int[inOrder.size()];
        for (int p = 0; p < materialOf.length; p++) {
            materialOf[p] = indexOf(materialList, inOrder.get(p).material());
        }
        materials = new Materials(materialList);
        shadowPass = new double[materialOf.length];
        for (int p = 0; p < materialOf.length && settings.shading() == Shading.PHONG; p++) {
            int m = materialOf[p];
            shadowPass[p] = materials.type(m) == MaterialType.GLASS ? materials.kt(m) : 0;
        }
        lights = new Lights(scene.lights());
        shadowAggregate = new Aggregate[lights.count()];
        for (int i = 0, points = 0; i < shadowAggregate.length; i++) {
            shadowAggregate[i] = lightCells && lights.isPoint(i) ? AggregatePolicy.forPointLight(aggregate, points++,
                    lights.position(i, 0), lights.position(i, 1), lights.position(i, 2)) : aggregate;
        }
        backgroundR = scene.background().x();
        backgroundG = scene.background().y();
        backgroundB = scene.background().z();
        ambientR = scene.ambient().x();
        ambientG = scene.ambient().y();
        ambientB = scene.ambient().z();
        camera = new CameraBasis(scene.camera());
    }

    /** The same compiled scene seen from another camera: shares everything else. */
    private RenderScene(RenderScene base, Camera camera) {
        settings = base.settings;
        primitives = base.primitives;
        aggregate = base.aggregate;
        shadowAggregate = base.shadowAggregate;
        materialOf = base.materialOf;
        materials = base.materials;
        lights = base.lights;
        shadowPass = base.shadowPass;
        backgroundR = base.backgroundR;
        backgroundG = base.backgroundG;
        backgroundB = base.backgroundB;
        ambientR = base.ambientR;
        ambientG = base.ambientG;
        ambientB = base.ambientB;
        this.camera = new CameraBasis(camera);
    }

    /** Compiles an immutable scene with the given settings. */
    public static RenderScene compile(Scene scene, RenderSettings settings) {
        return new RenderScene(scene, settings, AggregatePolicy::choose, true);
    }

    /**
     * Compiles a scene whose rays, shadow rays too, search the aggregate {@code aggregateOf} builds,
     * whatever the policy would choose.
     */
    static RenderScene compile(Scene scene, RenderSettings settings, Function<Primitives, Aggregate> aggregateOf) {
        return new RenderScene(scene, settings, aggregateOf, false);
    }

    /**
     * This scene from another camera, without recompiling it (no arrays copied, no hierarchy
     * rebuilt): what a window needs for every frame of a moving camera.
     */
    public RenderScene withCamera(Camera camera) {
        return new RenderScene(this, camera);
    }

    public RenderSettings settings() {
        return settings;
    }

    /** The aggregate every ray of this scene asks. */
    public Aggregate aggregate() {
        return aggregate;
    }

    private static List<SceneObject> unknownKind(SceneObject o) {
        throw new IllegalArgumentException("no primitive kind compiles " + o.shape().getClass().getSimpleName());
    }

    private static int indexOf(List<Material> materials, Material material) {
        int i = materials.indexOf(material);
        if (i >= 0) {
            return i;
        }
        materials.add(material);
        return materials.size() - 1;
    }

    private static void put4(double[] array, int i, double a, double b, double c, double d) {
        array[4 * i] = a;
        array[4 * i + 1] = b;
        array[4 * i + 2] = c;
        array[4 * i + 3] = d;
    }
}
