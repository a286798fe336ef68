package glint.shading;

/** Scratch value: linear RGB radiance or irradiance. */
public final class Rgb {

    public double r, g, b;

    public void set(double r, double g, double b) {
        this.r = r;
        this.g = g;
        this.b = b;
    }
}
