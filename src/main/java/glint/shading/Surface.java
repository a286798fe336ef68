package glint.shading;

import glint.geometry.Hit;

/**
 * Scratch value: the surface a ray met, as shading sees it (world space). The normal faces the
 * side the ray came from; rays leaving it start {@link #offset} off the surface, on that side
 * ({@link #nearX} ...) or through it ({@link #farX} ...), and skip the primitive where it cannot
 * be met again.
 */
public final class Surface {

    /** The point on the surface. */
    public double px, py, pz;
    /** The unit normal, facing the incoming ray. */
    public double nx, ny, nz;
    /** The cosine between the incoming ray's reverse and the normal, >= 0. */
    public double cosIncident;
    /** Whether the ray met the surface's outer side. */
    public boolean front;
    /** How far rays leaving the surface start off it: epsilon max(1, |p|). */
    public double offset;
    /** The material's number. */
    public int material;
    /** The primitive rays leaving on the incoming side skip, and rays leaving through it ({@link Hit#NONE}: none). */
    public int skipNear, skipFar;
    /**
     * The closed primitive rays leaving on the incoming side travel inside of (reflected inside a
     * sphere), and rays leaving through it (refracted into one); {@link Hit#NONE} for none.
     */
    public int insideNear, insideFar;

    /**
     * Fills this surface from a described hit of the unit ray from o along d: {@code epsilon}
     * scales the offset, {@code closed} says whether a ray entering the primitive can meet it again.
     */
    public void set(Hit hit, double ox, double oy, double oz, double dx, double dy, double dz, double epsilon,
                    int material, boolean closed) {
        // the offset scales with |p| before p is moved onto the surface: the move is far below a
        // rounding step of the offset
        double t = hit.t;
        double rawX = ox + t * dx, rawY = oy + t * dy, rawZ = oz + t * dz;
        offset = epsilon * atLeastOne(Math.sqrt(rawX * rawX + rawY * rawY + rawZ * rawZ));
        px = hit.px;
        py = hit.py;
        pz = hit.pz;
        double cos = -(dx * hit.nx + dy * hit.ny + dz * hit.nz); // > 0 when the ray meets the outer side
        front = cos >= 0;
        double sign = front ? 1 : -1;
        nx = sign * hit.nx;
        ny = sign * hit.ny;
        nz = sign * hit.nz;
        cosIncident = front ? cos : -cos;
        this.material = material;
        skipNear = !closed || front ? hit.primitive : Hit.NONE;
        skipFar = !closed || !front ? hit.primitive : Hit.NONE;
        insideNear = closed && !front ? hit.primitive : Hit.NONE;
        insideFar = closed && front ? hit.primitive : Hit.NONE;
    }

    /**
     * Fills this surface for a ray inside closed primitive {@code primitive} meeting its far side
     * at {@code end} (point on the surface, outward normal) at cosine {@code cosIncident}, known in
     * closed form ({@link glint.geometry.PrimitiveKind#chordInside}).
     */
    public void setInside(Hit end, double cosIncident, double epsilon, int material, int primitive) {
        px = end.px;
        py = end.py;
        pz = end.pz;
        offset = epsilon * atLeastOne(Math.sqrt(px * px + py * py + pz * pz));
        nx = -end.nx;
        ny = -end.ny;
        nz = -end.nz;
        this.cosIncident = cosIncident;
        front = false;
        this.material = material;
        skipNear = Hit.NONE;
        skipFar = primitive;
        insideNear = primitive;
        insideFar = Hit.NONE;
    }

    /** The origin of rays leaving on the incoming side: p + offset n. */
    public double nearX() {
        return px + offset * nx;
    }

    public double nearY() {
        return py + offset * ny;
    }

    public double nearZ() {
        return pz + offset * nz;
    }

    /** The origin of rays leaving through the surface: p - offset n. */
    public double farX() {
        return px - offset * nx;
    }

    public double farY() {
        return py - offset * ny;
    }

    public double farZ() {
        return pz - offset * nz;
    }

    /** max(1, distance) for a distance that is >= 0 and not NaN, with one comparison. */
    private static double atLeastOne(double distance) {
        return distance > 1 ? distance : 1;
    }
}
