package glint.study;

/**
 * How one ray-sphere method fared on one view. A pixel is wrong when its hit/miss decision differs
 * from the exact one, or when both hit and t differs from the exact t by more than
 * {@link SphereView#DISTANCE_TOLERANCE} x min(radius, exact t).
 *
 * @param pixels        pixels in the view
 * @param wrongHitMiss  pixels whose hit/miss decision is wrong (silhouette errors, holes, ghost hits)
 * @param wrongDistance pixels with the right decision but a hit distance off by more than the tolerance
 */
public record SphereErrors(int pixels, int wrongHitMiss, int wrongDistance) {

    public int wrong() {
        return wrongHitMiss + wrongDistance;
    }

    public double wrongFraction() {
        return (double) wrong() / pixels;
    }

    public double hitMissFraction() {
        return (double) wrongHitMiss / pixels;
    }
}
