package glint.render;

import glint.config.Shading;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.Light;
import glint.scene.Material;
import glint.scene.Plane;
import glint.scene.Scene;
import glint.scene.SceneObject;
import glint.scene.Sphere;
import java.util.ArrayList;
import java.util.List;

/**
 * A scene compiled for tracing: shapes, materials and lights in flat primitive arrays (world
 * space), the camera as a basis, and the settings. Immutable after construction; shared by all
 * workers.
 */
public final class RenderScene {

    static final int MATTE = 0;
    static final int METAL = 1;
    static final int GLASS = 2;

    /**
     * Scenes with more spheres than this get a bounding volume hierarchy. Camera and shadow rays
     * rarely search it ({@link EyeRays}, {@link LightBuffer}); for reflected and refracted rays it
     * pays from about 20 spheres. Millions of instructions a frame of the render thread (800x600,
     * 1 sample, depth 5, one thread), with and without a hierarchy: 10 glass spheres 632 and 584,
     * 15 glass 721 and 668, 20 glass 768 and 848, 25 glass 813 and 912; 10 matte 278 and 262, 20
     * matte 281 and 282.
     */
    static final int BVH_MIN_SPHERES = 16;

    /** Smallest GGX alpha used for a highlight; keeps D(h) finite as roughness -> 0. */
    static final double MIN_ALPHA = 1e-4;

    final RenderSettings settings;

    // spheres: centre x, y, z and radius, 4 doubles each
    final int sphereCount;
    final double[] spheres;
    final int[] sphereMaterial;
    /** Hierarchy over the spheres (which are stored in its order), or null for few spheres. */
    final SphereBvh bvh;
    /** Per sphere, whether nothing else reaches into it ({@link EmptySpheres}). */
    final boolean[] sphereIsEmpty;
    /**
     * Per sphere, the spheres a ray leaving it on its outer side can meet, by direction; null for a
     * sphere no ray leaves (matte, shaded physically) or beyond the budget.
     */
    final NeighbourCells[] neighbours;

    // planes: unit normal x, y, z and offset n.p, 4 doubles each
    final int planeCount;
    final double[] planes;
    final int[] planeMaterial;

    // materials, indexed by material id
    final int[] materialType;
    final double[] materialColor; // 3 per material, linear RGB
    final double[] kd;
    final double[] ks;
    final double[] kt;
    final double[] shininess;
    final double[] ior;
    final double[] alpha; // roughness^2; 0 = no highlight

    // lights: for a point light its position, for a directional one the unit direction towards it
    final int lightCount;
    final boolean[] lightIsPoint;
    final double[] lightVector; // 3 per light
    final double[] lightPower;  // 3 per light: color x intensity
    /**
     * Per point light, the spheres that can shadow it by direction: as cones in a scene of few
     * spheres, otherwise as a light buffer; both null for a directional light.
     */
    final LightCones[] lightCones;
    final LightBuffer[] lightBuffers;

    final double backgroundR, backgroundG, backgroundB;
    final double ambientR, ambientG, ambientB;

    /** The camera, world space. */
    final CameraBasis camera;

    private RenderScene(Scene scene, RenderSettings settings) {
        this.settings = settings;
        List<Material> materials = new ArrayList<>();
        List<SceneObject> sphereObjects = new ArrayList<>();
        List<SceneObject> planeObjects = new ArrayList<>();
        for (SceneObject o : scene.objects()) {
            (o.shape() instanceof Sphere ? sphereObjects : planeObjects).add(o);
        }
        sphereCount = sphereObjects.size();
        spheres = new double[4 * sphereCount];
        sphereMaterial = new int[sphereCount];
        for (int i = 0; i < sphereCount; i++) {
            Sphere s = (Sphere) sphereObjects.get(i).shape();
            put4(spheres, i, s.center(), s.radius());
            sphereMaterial[i] = indexOf(materials, sphereObjects.get(i).material());
        }
        bvh = sphereCount > BVH_MIN_SPHERES ? SphereBvh.build(spheres, sphereCount) : null;
        if (bvh != null) {
            reorderSpheres(bvh.order);
        }
        planeCount = planeObjects.size();
        planes = new double[4 * planeCount];
        planeMaterial = new int[planeCount];
        for (int i = 0; i < planeCount; i++) {
            Plane p = (Plane) planeObjects.get(i).shape();
            put4(planes, i, p.normal(), p.normal().dot(p.point()));
            planeMaterial[i] = indexOf(materials, planeObjects.get(i).material());
        }
        sphereIsEmpty = EmptySpheres.find(spheres, sphereCount, planes, planeCount, bvh);

        int m = materials.size();
        materialType = new int[m];
        materialColor = new double[3 * m];
        kd = new double[m];
        ks = new double[m];
        kt = new double[m];
        shininess = new double[m];
        ior = new double[m];
        alpha = new double[m];
        for (int i = 0; i < m; i++) {
            Material mat = materials.get(i);
            materialType[i] = mat.type().ordinal();
            put3(materialColor, i, mat.color());
            kd[i] = mat.kd();
            ks[i] = mat.ks();
            kt[i] = mat.kt();
            shininess[i] = mat.shininess();
            ior[i] = mat.ior();
            double a = mat.roughness() * mat.roughness();
            alpha[i] = mat.roughness() > 0 ? Math.max(a, MIN_ALPHA) : 0;
        }

        lightCount = scene.lights().size();
        lightIsPoint = new boolean[lightCount];
        lightVector = new double[3 * lightCount];
        lightPower = new double[3 * lightCount];
        for (int i = 0; i < lightCount; i++) {
            Light light = scene.lights().get(i);
            if (light instanceof Light.Point p) {
                lightIsPoint[i] = true;
                put3(lightVector, i, p.position());
            } else {
                put3(lightVector, i, ((Light.Directional) light).direction().scale(-1));
            }
            put3(lightPower, i, light.color().scale(light.intensity()));
        }
        lightCones = buildLightCones();
        lightBuffers = buildLightBuffers();
        neighbours = buildNeighbourCells();

        backgroundR = scene.background().x();
        backgroundG = scene.background().y();
        backgroundB = scene.background().z();
        ambientR = scene.ambient().x();
        ambientG = scene.ambient().y();
        ambientB = scene.ambient().z();

        camera = new CameraBasis(scene.camera());
    }

    /** The same compiled scene seen from another camera: shares every array, rebuilds nothing. */
    private RenderScene(RenderScene base, Camera camera) {
        settings = base.settings;
        sphereCount = base.sphereCount;
        spheres = base.spheres;
        sphereMaterial = base.sphereMaterial;
        bvh = base.bvh;
        sphereIsEmpty = base.sphereIsEmpty;
        neighbours = base.neighbours;
        planeCount = base.planeCount;
        planes = base.planes;
        planeMaterial = base.planeMaterial;
        materialType = base.materialType;
        materialColor = base.materialColor;
        kd = base.kd;
        ks = base.ks;
        kt = base.kt;
        shininess = base.shininess;
        ior = base.ior;
        alpha = base.alpha;
        lightCount = base.lightCount;
        lightIsPoint = base.lightIsPoint;
        lightVector = base.lightVector;
        lightPower = base.lightPower;
        lightCones = base.lightCones;
        lightBuffers = base.lightBuffers;
        backgroundR = base.backgroundR;
        backgroundG = base.backgroundG;
        backgroundB = base.backgroundB;
        ambientR = base.ambientR;
        ambientG = base.ambientG;
        ambientB = base.ambientB;
        this.camera = new CameraBasis(camera);
    }

    /** Light buffers for at most this many point lights; shadow rays towards the others take the full test. */
    static final int MOST_LIGHT_BUFFERS = 8;
    /** List entries and cell indices all light buffers together may hold: 32 MB. */
    static final long LIGHT_BUFFER_ENTRIES = 8L << 20;

    /** {@link LightCones} for each point light, in a scene of at most {@link LightCones#MOST_SPHERES} spheres. */
    private LightCones[] buildLightCones() {
        LightCones[] cones = new LightCones[lightCount];
        for (int i = 0; i < lightCount && sphereCount > 0 && sphereCount <= LightCones.MOST_SPHERES; i++) {
            if (lightIsPoint[i]) {
                cones[i] = LightCones.build(spheres, sphereCount, lightVector[3 * i], lightVector[3 * i + 1],
                        lightVector[3 * i + 2]);
            }
        }
        return cones;
    }

    /**
     * In a scene of more spheres than {@link LightCones#MOST_SPHERES}, a {@link LightBuffer} for
     * each of the first point lights, while they fit the budget: a scene of many lights, or of many
     * spheres crowding around one, must not cost the memory or the compile time of a buffer for
     * each.
     */
    private LightBuffer[] buildLightBuffers() {
        LightBuffer[] buffers = new LightBuffer[lightCount];
        long left = LIGHT_BUFFER_ENTRIES;
        int built = 0;
        for (int i = 0; i < lightCount && built < MOST_LIGHT_BUFFERS && sphereCount > LightCones.MOST_SPHERES; i++) {
            if (!lightIsPoint[i] || left < LightBuffer.CELL_INDEX_SIZE) {
                continue;
            }
            LightBuffer buffer = LightBuffer.build(spheres, sphereCount, lightVector[3 * i], lightVector[3 * i + 1],
                    lightVector[3 * i + 2], left - LightBuffer.CELL_INDEX_SIZE);
            if (buffer != null) {
                buffers[i] = buffer;
                left -= LightBuffer.CELL_INDEX_SIZE + buffer.entries();
                built++;
            }
        }
        return buffers;
    }

    /**
     * Scenes with fewer spheres than this search them all for reflected and refracted rays: a few
     * sphere tests cost less than a cell lookup. Millions of instructions a frame of the render
     * thread (800x600, 1 sample, depth 5, one thread), without and with {@link NeighbourCells}:
     * default scene 464-474 and 488-495, 5 glass spheres 392-408 and 398-402, 10 glass 524-621 and
     * 486-516, 25 glass 761-768 and 629-672 (docs/benchmarks.md, "Rays leaving a sphere").
     */
    static final int NEIGHBOUR_MIN_SPHERES = 8;
    /**
     * Scenes with more spheres than this search the hierarchy instead: every sphere's cells list
     * every other sphere, so their size and build time grow as the square of the count (1,000
     * spheres: 0.8 s and 55 MB more to load, against 0.9 s and 80 MB in all without them).
     */
    static final int NEIGHBOUR_MAX_SPHERES = 64;

    /** List entries and cell indices all neighbour cells together may hold: 8 MB of indices, 16 MB of distances. */
    static final long NEIGHBOUR_ENTRIES = 2L << 20;

    /**
     * {@link NeighbourCells} for each sphere that reflected or refracted rays leave, while they fit
     * the budget. A ray leaves sphere i from at most epsilon max(1, |p|) off its surface, |p| at most
     * |centre| + r: the reach of its cells, with a margin for rounding.
     */
    private NeighbourCells[] buildNeighbourCells() {
        NeighbourCells[] cells = new NeighbourCells[sphereCount];
        if (sphereCount < NEIGHBOUR_MIN_SPHERES || sphereCount > NEIGHBOUR_MAX_SPHERES) {
            return cells;
        }
        long left = NEIGHBOUR_ENTRIES;
        boolean phong = settings.shading() == Shading.PHONG;
        for (int i = 0; i < sphereCount; i++) {
            if ((!phong && materialType[sphereMaterial[i]] == MATTE) || left < NeighbourCells.CELL_INDEX_SIZE) {
                continue;
            }
            int k = 4 * i;
            double radius = spheres[k + 3];
            double farthest = Math.sqrt(spheres[k] * spheres[k] + spheres[k + 1] * spheres[k + 1]
                    + spheres[k + 2] * spheres[k + 2]) + radius;
            double reach = radius + settings.epsilon() * Math.max(1, farthest) * (1 + 1e-6) + 1e-9 * farthest;
            NeighbourCells built = NeighbourCells.build(spheres, sphereCount, i, reach,
                    left - NeighbourCells.CELL_INDEX_SIZE);
            if (built != null) {
                cells[i] = built;
                left -= NeighbourCells.CELL_INDEX_SIZE + built.entries();
            }
        }
        return cells;
    }

    /**
     * This scene from another camera, without recompiling it (no arrays copied, no hierarchy
     * rebuilt): what a window needs for every frame of a moving camera.
     */
    public RenderScene withCamera(Camera camera) {
        return new RenderScene(this, camera);
    }

    /** Compiles an immutable scene with the given settings. */
    public static RenderScene compile(Scene scene, RenderSettings settings) {
        return new RenderScene(scene, settings);
    }

    public RenderSettings settings() {
        return settings;
    }

    /** Whether a scene of {@code spheres} spheres is searched through a hierarchy. */
    public static boolean usesHierarchy(int spheres) {
        return spheres > BVH_MIN_SPHERES;
    }

    public boolean hasHierarchy() {
        return bvh != null;
    }

    /** The fraction of light a phong shadow ray passes through an object of this material. */
    double shadowPass(int material) {
        return materialType[material] == GLASS ? kt[material] : 0;
    }

    private void reorderSpheres(int[] order) {
        double[] oldSpheres = spheres.clone();
        int[] oldMaterial = sphereMaterial.clone();
        for (int i = 0; i < order.length; i++) {
            System.arraycopy(oldSpheres, 4 * order[i], spheres, 4 * i, 4);
            sphereMaterial[i] = oldMaterial[order[i]];
        }
    }

    private static int indexOf(List<Material> materials, Material material) {
        int i = materials.indexOf(material);
        if (i >= 0) {
            return i;
        }
        materials.add(material);
        return materials.size() - 1;
    }

    private static void put3(double[] array, int index, Vector3d v) {
        array[3 * index] = v.x();
        array[3 * index + 1] = v.y();
        array[3 * index + 2] = v.z();
    }

    private static void put4(double[] array, int index, Vector3d v, double w) {
        array[4 * index] = v.x();
        array[4 * index + 1] = v.y();
        array[4 * index + 2] = v.z();
        array[4 * index + 3] = w;
    }
}
