package glint.shading;

/**
 * Scratch value: linear RGB radiance or irradiance. What is set is at most {@link #LARGEST}, so a
 * path of many bright bounces stays a finite double (never infinity, which a factor of 0 further on
 * would make NaN) and stays brighter than a frame can store, which stores it as its largest float.
 */
public final class Rgb {

    /**
     * The most a value set holds: far above the largest float a frame stores (3.4e38), and far below
     * the largest double, so that a bounce's factors (at most 1e60: kt 1e30 x colour 1e30) keep it finite.
     */
    static final double LARGEST = 1e200;

    public double r, g, b;

    public void set(double r, double g, double b) {
        this.r = Math.min(r, LARGEST);
        this.g = Math.min(g, LARGEST);
        this.b = Math.min(b, LARGEST);
    }
}
