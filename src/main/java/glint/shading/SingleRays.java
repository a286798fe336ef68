package glint.shading;

/**
 * Scratch value: the factors of the single rays Whitted's integrator follows from a surface in
 * place of its lobes ({@link WhittedResponse#specular}): the mirrored ray's per channel and, where the surface
 * refracts, eta = n_incident / n_transmitted and the tint of the refracted ray (0 for none).
 */
public final class SingleRays {

    public double reflectR, reflectG, reflectB;
    public double eta;
    public double transmitR, transmitG, transmitB;

    public void setReflect(double r, double g, double b) {
        reflectR = r;
        reflectG = g;
        reflectB = b;
    }

    public void setTransmit(double r, double g, double b) {
        transmitR = r;
        transmitG = g;
        transmitB = b;
    }

    /** The largest factor of the mirrored ray. */
    public double reflectMax() {
        return Math.max(reflectR, Math.max(reflectG, reflectB));
    }

    /** The largest channel of the refracted ray's tint. */
    public double transmitMax() {
        return Math.max(transmitR, Math.max(transmitG, transmitB));
    }

    /** Makes these the factors {@code other} holds. */
    public void setTo(SingleRays other) {
        eta = other.eta;
        setReflect(other.reflectR, other.reflectG, other.reflectB);
        setTransmit(other.transmitR, other.transmitG, other.transmitB);
    }
}
