package glint.render;

/**
 * Traces camera rays four at a time: the SIMD path, one lane per ray. A packet is traced whole
 * only when its four rays stay together (all miss, or all meet the same matte surface from its
 * front); otherwise the caller traces its rays one by one. Either way the radiance is the plain
 * path's, bit for bit: the lanes do the scalar arithmetic in the scalar order.
 */
interface CameraPackets {

    /** Rays in a packet. */
    int LANES = 4;

    /** The module the implementation needs; present only when the JVM was started with --add-modules. */
    String VECTOR_MODULE = "jdk.incubator.vector";

    /**
     * True when scenes of this kind can be traced in packets: cook-torrance shading and spheres searched
     * one by one (a scene with a hierarchy, or phong shading, takes the plain path).
     */
    boolean handles(RenderScene scene);

    /**
     * Traces camera rays [first, first + 4) of a row, aimed along dirX/Y/Z and after
     * {@link EyeRays#aimRow} for the row holding them, into radianceR/G/B at the same
     * indices; returns false, having written nothing, when the packet does not stay together.
     */
    boolean trace(RenderScene scene, RayCaster eye, double[] dirX, double[] dirY, double[] dirZ, int first,
                  double[] radianceR, double[] radianceG, double[] radianceB);

    /** Whether the Vector API module is loaded in this JVM. */
    static boolean available() {
        return ModuleLayer.boot().findModule(VECTOR_MODULE).isPresent();
    }

    /**
     * The Vector API implementation when its module is loaded, else null. Loaded by name, so that
     * without the module no class that names it is ever linked.
     */
    static CameraPackets load() {
        if (!available()) {
            return null;
        }
        try {
            return (CameraPackets) Class.forName("glint.render.VectorCameraPackets")
                    .getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException | LinkageError e) {
            return null;
        }
    }
}
