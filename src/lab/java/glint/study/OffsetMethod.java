package glint.study;

import glint.render.Tracer;

/**
 * A way to start a shadow ray off a surface, as compared by the self-intersection study: the
 * textbook fixed epsilon (modelled here, float or double) or Glint's renderer with its offset
 * epsilon x max(1, |p|) off a re-projected hit point.
 */
public sealed interface OffsetMethod permits OffsetMethod.Fixed, OffsetMethod.Glint {

    String label();

    /** Per pixel: true when the method shows the point lit. */
    boolean[] lit(ShadowScene scene, Tracer tracer);

    /** The offset this method applies at a point of magnitude |p|. */
    double offset(double pointNorm);

    /** Fixed epsilon, hit point o + t d, in the given precision. */
    record Fixed(Precision precision, double epsilon) implements OffsetMethod {
        @Override
        public String label() {
            return "fixed " + Numbers.sci(epsilon) + ", " + precision.name().toLowerCase(java.util.Locale.ROOT);
        }

        @Override
        public boolean[] lit(ShadowScene scene, Tracer tracer) {
            return new FixedEpsilonModel(precision, epsilon).lit(scene);
        }

        @Override
        public double offset(double pointNorm) {
            return epsilon;
        }
    }

    /** Glint, rendered: epsilon x max(1, |p|), re-projected hit point, double. */
    record Glint(double epsilon) implements OffsetMethod {
        @Override
        public String label() {
            return "Glint, epsilon " + Numbers.sci(epsilon) + " x max(1, |p|)";
        }

        @Override
        public boolean[] lit(ShadowScene scene, Tracer tracer) {
            return GlintOffset.lit(scene, epsilon, tracer);
        }

        @Override
        public double offset(double pointNorm) {
            return epsilon * Math.max(1, pointNorm);
        }
    }
}
