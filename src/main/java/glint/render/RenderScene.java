package glint.render;

import glint.accel.Aggregate;
import glint.accel.AggregatePolicy;
import glint.geometry.Hit;
import glint.geometry.PrimitiveKind;
import glint.geometry.Primitives;
import glint.math.Vector3d;
import glint.registry.LightType;
import glint.registry.Registry;
import glint.registry.ShapeType;
import glint.scene.Camera;
import glint.scene.Light;
import glint.scene.Material;
import glint.scene.Scene;
import glint.scene.SceneObject;
import glint.scene.Shape;
import glint.shading.LampBody;
import glint.shading.LightTargets;
import glint.shading.Lights;
import glint.shading.Lobe;
import glint.shading.Materials;
import glint.shading.SkySampler;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

/**
 * A scene compiled for tracing: its primitives by kind in flat arrays and the aggregate that
 * searches them, materials and lights in flat arrays, the camera that makes its rays, and the settings.
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
    /** Per primitive: the number of the light whose body it is, or -1. */
    final int[] lightOf;
    /** Per light: the primitive that is its body, or {@link Hit#NONE}. */
    final int[] bodyOf;
    /** How many lights have a size (are not delta lights): a BSDF sample may meet them. */
    final int lightsWithSize;
    final Materials materials;
    final Lights lights;
    /**
     * The lights, then the sky where the background is not black ({@link SkySampler}, number
     * {@code lights.count()}): every light a bidirectional path starts from.
     */
    final Lights lightsAndSky;
    /**
     * Per primitive: the fraction of light a shadow ray passes through it. The cook-torrance model
     * passes none; the phong model passes kt through glass.
     */
    final double[] shadowPass;
    final double backgroundR, backgroundG, backgroundB;
    final double ambientR, ambientG, ambientB;
    /** The camera that makes the camera rays, world space: a pinhole, or a thin lens. */
    final CameraModel camera;
    /**
     * The one strategy (s, t) a bidirectional render keeps, weighted or not, for the tests and studies
     * that look at strategies one by one (pbrt's visualize-strategies); -1: every strategy, weighted;
     * {@link #MERGES}: the merges alone.
     */
    final int strategyS, strategyT;
    final boolean strategyWeighted;
    /** The balls around the objects that focus light, which bidirectional light subpaths aim at. */
    final LightTargets lightTargets;

    private RenderScene(Scene scene, RenderSettings settings, Registry registry,
                        Function<Primitives, Aggregate> aggregateOf, boolean lightCells) {
        this.settings = settings;
        List<LightType.Compiled> compiledLights = new ArrayList<>();
        for (Light light : scene.lights()) {
            compiledLights.add(registry.typeOf(light).compile(light));
        }
        // the scene's objects, then the lights' bodies, each light's with its number
        List<SceneObject> objects = new ArrayList<>(scene.objects());
        Map<SceneObject, Integer> bodies = new IdentityHashMap<>();
        for (int i = 0; i < compiledLights.size(); i++) {
            Shape body = compiledLights.get(i).body();
            if (body != null) {
                SceneObject o = new SceneObject(body, null);
                objects.add(o);
                bodies.put(o, i);
            }
        }
        List<SceneObject> inOrder = new ArrayList<>(); // kind by kind, in the registry's order
        primitives = new Primitives(kinds(objects, registry, inOrder));
        aggregate = aggregateOf.apply(primitives);
        List<Material> materialList = new ArrayList<>();
        materialOf = new int[inOrder.size()];
        lightOf = new int[inOrder.size()];
        for (int p = 0; p < materialOf.length; p++) {
            Integer light = bodies.get(inOrder.get(p));
            lightOf[p] = light == null ? -1 : light;
            materialOf[p] = light == null ? indexOf(materialList, inOrder.get(p).material()) : -1;
        }
        List<Materials.Material> compiledMaterials = new ArrayList<>(materialList.stream()
                .map(m -> registry.material(m.type()).compile(m)).toList());
        int[] bodyMaterial = new int[compiledLights.size()];
        for (int i = 0; i < compiledLights.size(); i++) {
            if (compiledLights.get(i).body() != null) {
                bodyMaterial[i] = compiledMaterials.size();
                compiledMaterials.add(LampBody.material(compiledLights.get(i).bodyRadiance()));
            }
        }
        for (int p = 0; p < materialOf.length; p++) {
            if (lightOf[p] >= 0) {
                materialOf[p] = bodyMaterial[lightOf[p]];
            }
        }
        materials = Materials.of(compiledMaterials, settings.glassFresnel() == RenderSettings.GlassFresnel.EXACT);
        shadowPass = new double[materialOf.length];
        for (int p = 0; p < materialOf.length && settings.shading() == Shading.PHONG; p++) {
            int m = materialOf[p];
            shadowPass[p] = materials.response(m).transmits() ? materials.kt(m) : 0;
        }
        lights = Lights.of(compiledLights.stream().map(LightType.Compiled::light).toList());
        this.bodyOf = new int[lights.count()];
        Arrays.fill(this.bodyOf, Hit.NONE);
        for (int p = 0; p < lightOf.length; p++) {
            if (lightOf[p] >= 0) {
                bodyOf[lightOf[p]] = p;
            }
        }
        List<Lights.Light> withSky = new ArrayList<>(compiledLights.stream().map(LightType.Compiled::light).toList());
        Vector3d sky = scene.background();
        if (sky.x() > 0 || sky.y() > 0 || sky.z() > 0) {
            withSky.add(new Lights.Light(new SkySampler(), SkySampler.data(sky.x(), sky.y(), sky.z()), null));
        }
        lightsAndSky = Lights.of(withSky);
        int withSize = 0;
        for (int i = 0; i < lights.count(); i++) {
            withSize += lights.isDelta(i) ? 0 : 1;
        }
        lightsWithSize = withSize;
        shadowAggregate = new Aggregate[lights.count()];
        for (int i = 0, points = 0; i < shadowAggregate.length; i++) {
            shadowAggregate[i] = lightCells && lights.atPoint(i) ? AggregatePolicy.forPointLight(aggregate, points++,
                    lights.position(i, 0), lights.position(i, 1), lights.position(i, 2)) : aggregate;
        }
        backgroundR = scene.background().x();
        backgroundG = scene.background().y();
        backgroundB = scene.background().z();
        ambientR = scene.ambient().x();
        ambientG = scene.ambient().y();
        ambientB = scene.ambient().z();
        camera = CameraModel.of(scene.camera());
        lightTargets = lightTargets(primitives, materialOf, lightOf, materials);
        strategyS = -1;
        strategyT = -1;
        strategyWeighted = true;
    }

    /**
     * The balls around the bounded primitives whose material has no diffuse lobe (glass and metal: what
     * focuses light into caustics), lights' bodies left out.
     */
    private static LightTargets lightTargets(Primitives primitives, int[] materialOf, int[] lightOf,
                                             Materials materials) {
        double[] balls = new double[4 * primitives.count()], ball = new double[4];
        int n = 0;
        for (int p = 0; p < primitives.count(); p++) {
            if (primitives.bounded(p) && lightOf[p] < 0 && (materials.lobes(materialOf[p]) & Lobe.DIFFUSE) == 0) {
                primitives.kind(primitives.kindOf(p)).boundingBall(primitives.indexOf(p), ball);
                System.arraycopy(ball, 0, balls, 4 * n++, 4);
            }
        }
        return LightTargets.of(Arrays.copyOf(balls, 4 * n));
    }

    /** The same compiled scene seen from another camera: shares everything else. */
    private RenderScene(RenderScene base, CameraModel camera) {
        this(base, camera, base.strategyS, base.strategyT, base.strategyWeighted);
    }

    private RenderScene(RenderScene base, CameraModel camera, int strategyS, int strategyT, boolean weighted) {
        settings = base.settings;
        primitives = base.primitives;
        aggregate = base.aggregate;
        shadowAggregate = base.shadowAggregate;
        materialOf = base.materialOf;
        lightOf = base.lightOf;
        bodyOf = base.bodyOf;
        lightsWithSize = base.lightsWithSize;
        materials = base.materials;
        lights = base.lights;
        lightsAndSky = base.lightsAndSky;
        shadowPass = base.shadowPass;
        backgroundR = base.backgroundR;
        backgroundG = base.backgroundG;
        backgroundB = base.backgroundB;
        ambientR = base.ambientR;
        ambientG = base.ambientG;
        ambientB = base.ambientB;
        this.camera = camera;
        lightTargets = base.lightTargets;
        this.strategyS = strategyS;
        this.strategyT = strategyT;
        this.strategyWeighted = weighted;
    }

    /**
     * This scene rendered by the bidirectional integrator with strategy (s, t) alone, or its merges alone
     * (s = t = {@link #MERGES}), by its weight or unweighted ({@code BdptIntegrator}): what the tests and
     * studies of its strategies render.
     */
    RenderScene withStrategy(int s, int t, boolean weighted) {
        return new RenderScene(this, camera, s, t, weighted);
    }

    /** The strategy that stands for every merge of a bidirectional render ({@link #withStrategy}). */
    static final int MERGES = -2;

    /** Compiles an immutable scene with the given settings. */
    public static RenderScene compile(Scene scene, RenderSettings settings) {
        return compile(scene, settings, Registry.STANDARD);
    }

    /** Compiles a scene whose objects and lights may be of any type {@code registry} lists. */
    public static RenderScene compile(Scene scene, RenderSettings settings, Registry registry) {
        return new RenderScene(scene, settings, registry, AggregatePolicy::choose, true);
    }

    /**
     * Compiles a scene whose rays, shadow rays too, search the aggregate {@code aggregateOf} builds,
     * whatever the policy would choose.
     */
    static RenderScene compile(Scene scene, RenderSettings settings, Function<Primitives, Aggregate> aggregateOf) {
        return new RenderScene(scene, settings, Registry.STANDARD, aggregateOf, false);
    }

    /**
     * This scene from another camera, without recompiling it (no arrays copied, no hierarchy
     * rebuilt): what a window needs for every frame of a moving camera.
     */
    public RenderScene withCamera(Camera camera) {
        return new RenderScene(this, CameraModel.of(camera));
    }

    /** This scene through a camera model of the caller's (one no scene camera compiles to), without recompiling it. */
    public RenderScene withCamera(CameraModel model) {
        return new RenderScene(this, model);
    }

    public RenderSettings settings() {
        return settings;
    }

    /** The aggregate every ray of this scene asks. */
    public Aggregate aggregate() {
        return aggregate;
    }

    /**
     * The scene's primitives kind by kind, one kind per shape type of the registry (in its order);
     * each primitive's object, in that order, is added to {@code inOrder}.
     */
    private static List<PrimitiveKind> kinds(List<SceneObject> objects, Registry registry,
                                             List<SceneObject> inOrder) {
        List<PrimitiveKind> kinds = new ArrayList<>();
        for (ShapeType<?> type : registry.shapes()) {
            List<Shape> shapes = new ArrayList<>();
            for (SceneObject o : objects) {
                if (type.holds(o.shape())) {
                    shapes.add(o.shape());
                    for (int k = type.primitives(o.shape()); k > 0; k--) {
                        inOrder.add(o);
                    }
                }
            }
            kinds.add(type.compile(shapes));
        }
        for (SceneObject o : objects) {
            if (registry.shapes().stream().noneMatch(type -> type.holds(o.shape()))) {
                throw new IllegalArgumentException("no primitive kind compiles " + o.shape().getClass().getSimpleName());
            }
        }
        return kinds;
    }

    private static int indexOf(List<Material> materials, Material material) {
        int i = materials.indexOf(material);
        if (i >= 0) {
            return i;
        }
        materials.add(material);
        return materials.size() - 1;
    }
}
