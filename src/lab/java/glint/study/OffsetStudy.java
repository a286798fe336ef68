package glint.study;

import glint.render.Tracer;

/** Runs an {@link OffsetMethod} on a {@link ShadowScene} and judges it against the truth. */
public final class OffsetStudy {

    private OffsetStudy() {
    }

    /**
     * The scene moved by (s, s, s), judged against the truth of the scene at the origin (the pixel
     * rays and what they see do not change with the move).
     */
    public static OffsetErrors moved(ShadowScene atOrigin, ShadowTruth truth, double s, OffsetMethod method,
                                     Tracer tracer) {
        boolean[] lit = method.lit(atOrigin.translated(s), tracer);
        return OffsetErrors.of(truth, lit, pixel -> method.offset(truth.hitPointNorm(pixel, s)));
    }

    public static OffsetErrors moved(ShadowScene atOrigin, double s, OffsetMethod method, Tracer tracer) {
        return moved(atOrigin, ShadowTruth.of(atOrigin), s, method, tracer);
    }
}
