package glint.scene;

import glint.math.Vector3d;

/** A light of the scene model: plain data, whose type's registration says how it is read and sampled. */
public interface Light {

    /** The colour; {@code color} times {@code intensity} is the light's power. */
    Vector3d color();

    double intensity();

    /**
     * A point light of radiant intensity color x intensity, falling off as 1/d^2; with a
     * {@code radius} above 0, a sphere light of the same power whose surface sends radiance
     * color x intensity / (pi radius^2).
     */
    record Point(Vector3d position, Vector3d color, double intensity, double radius) implements Light {

        /** A point light of size 0. */
        public Point(Vector3d position, Vector3d color, double intensity) {
            this(position, color, intensity, 0);
        }
    }

    /**
     * A directional light; {@code direction} (unit) is the way its light travels. With an
     * {@code angleDegrees} above 0, a sun: a disc of that apparent diameter and uniform radiance,
     * giving irradiance color x intensity on a surface facing its centre.
     */
    record Directional(Vector3d direction, Vector3d color, double intensity, double angleDegrees) implements Light {

        /** A directional light of size 0. */
        public Directional(Vector3d direction, Vector3d color, double intensity) {
            this(direction, color, intensity, 0);
        }
    }
}
