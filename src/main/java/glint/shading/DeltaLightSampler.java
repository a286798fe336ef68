package glint.shading;

/**
 * A light of size 0 (a point, a direction): all its light arrives at a point from one direction, which
 * only its sample finds; no direction has a density, and no ray meets it.
 */
public interface DeltaLightSampler extends LightSampler {

    @Override
    default double pdf(double[] data, int at, double px, double py, double pz, double wx, double wy, double wz) {
        return 0;
    }

    @Override
    default boolean isDelta() {
        return true;
    }
}
