package glint.study;

/**
 * Self-intersection outcome of one method on one scene, against {@link ShadowTruth}.
 *
 * @param litPixels      pixels truly lit
 * @param acne           lit pixels shown dark although their shadow ray clears every occluder by more
 *                       than the method's offset: the ray met the surface it left (or rounding moved
 *                       the geometry)
 * @param overshoot      lit pixels shown dark whose clearance is below the offset: the offset itself
 *                       pushed the ray's origin into a neighbour, or past the light
 * @param shadowPixels   pixels truly in a cast shadow
 * @param missedShadow   shadow pixels shown lit
 * @param unexplained    missed shadow pixels whose shadow ray passes deeper inside the occluder than
 *                       the offset, which no offset of that size can cause (rounding of the geometry)
 */
public record OffsetErrors(int litPixels, int acne, int overshoot, int shadowPixels, int missedShadow,
                           int unexplained) {

    /** The offset a method applies at a pixel (given by index). */
    public interface OffsetAt {
        double at(int pixel);
    }

    public double acneFraction() {
        return litPixels == 0 ? 0 : (double) acne / litPixels;
    }

    public double overshootFraction() {
        return litPixels == 0 ? 0 : (double) overshoot / litPixels;
    }

    public double missedFraction() {
        return shadowPixels == 0 ? 0 : (double) missedShadow / shadowPixels;
    }

    /** Compares per-pixel lit flags with the truth, given the offset the method used at each pixel. */
    public static OffsetErrors of(ShadowTruth truth, boolean[] lit, OffsetAt offset) {
        int litPixels = 0, acne = 0, overshoot = 0, shadowPixels = 0, missed = 0, unexplained = 0;
        for (int i = 0; i < truth.pixels(); i++) {
            if (truth.kind(i) == ShadowTruth.LIT) {
                litPixels++;
                if (!lit[i]) {
                    if (truth.depth(i) > offset.at(i)) {
                        acne++;
                    } else {
                        overshoot++;
                    }
                }
            } else if (truth.kind(i) == ShadowTruth.SHADOW) {
                shadowPixels++;
                if (lit[i]) {
                    missed++;
                    unexplained += truth.depth(i) > offset.at(i) ? 1 : 0;
                }
            }
        }
        return new OffsetErrors(litPixels, acne, overshoot, shadowPixels, missed, unexplained);
    }
}
