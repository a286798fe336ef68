package glint.scene;

import glint.math.Vector3d;

/** A light of the scene model: plain data, whose type's registration says how it is read and sampled. */
public interface Light {

    /** The colour; {@code color} times {@code intensity} is the light's power. */
    Vector3d color();

    double intensity();

    /** A point light of radiant intensity color x intensity, falling off as 1/d^2. */
    record Point(Vector3d position, Vector3d color, double intensity) implements Light {
    }

    /** A directional light; {@code direction} (unit) is the way its light travels. */
    record Directional(Vector3d direction, Vector3d color, double intensity) implements Light {
    }
}
