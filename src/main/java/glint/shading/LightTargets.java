package glint.shading;

/**
 * The balls around the objects that focus light (glass and metal: no diffuse lobe) that a light
 * subpath leaving a light with a position aims at for part of its rays, as photon maps aim at the
 * objects that make caustics (Jensen 2001, "projection maps"). A ray leaves by the light's own
 * density with chance 1 - {@link #AIMED}, and otherwise towards a target chosen uniformly, spread
 * uniformly over the cone the target's ball fills; its density is the mixture of the two, so every
 * direction the light reaches is still reached and the estimate stays unbiased. Light focused by a
 * glass ball a few per cent of the light's sky wide is then traced tens of times as often. A light at
 * infinity, whose rays cross a disc across the scene, aims the same way: at a point of a target's shadow
 * on the disc.
 */
public final class LightTargets {

    /**
     * The chance that a ray leaving a light aims at a target. Measured with bdpt at 200 x 150 against
     * the references of caustic-lamp and lamp-and-frost (../shared/reference-pt), at 16 and 64 samples:
     * relMSE and FLIP fall as the share aimed grows from 0 to 0.25, 0.5, 0.75 and 0.9 (caustic-lamp at
     * 16: relMSE 3.2e-2, 2.2e-2, 1.9e-2, 1.7e-2, 1.6e-2); three quarters takes most of that gain and
     * leaves a quarter to the light's own rays, so that the strategies that need those (light reaching
     * matte surfaces from the light's end) lose at most 4 times their density.
     */
    public static final double AIMED = 0.75;
    /**
     * The most targets aimed at one by one; a scene with more aims at the ball around them all, so that
     * a density costs at most this many cone tests.
     */
    public static final int MOST_TARGETS = 16;

    private static final LightTargets NONE = new LightTargets(new double[0]);

    /** Each target's centre x, y, z and radius. */
    private final double[] balls;
    private final int count;

    /** @param balls centre x, y, z and radius of each target, 4 numbers each (copied) */
    private LightTargets(double[] balls) {
        this.balls = balls.clone();
        this.count = balls.length / 4;
    }

    /** No target: every ray leaves by its light's own density. */
    public static LightTargets none() {
        return NONE;
    }

    /**
     * Targets of the balls given (centre x, y, z and radius, 4 numbers each): each alone up to
     * {@link #MOST_TARGETS}, else one ball around them all.
     */
    public static LightTargets of(double[] balls) {
        if (balls.length / 4 <= MOST_TARGETS) {
            return new LightTargets(balls);
        }
        return new LightTargets(around(balls));
    }

    /** A ball around every ball given: centred at their boxes' centre. */
    private static double[] around(double[] balls) {
        double[] low = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] high = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int k = 0; k < balls.length; k += 4) {
            for (int a = 0; a < 3; a++) {
                low[a] = Math.min(low[a], balls[k + a] - balls[k + 3]);
                high[a] = Math.max(high[a], balls[k + a] + balls[k + 3]);
            }
        }
        double cx = (low[0] + high[0]) / 2, cy = (low[1] + high[1]) / 2, cz = (low[2] + high[2]) / 2;
        double r = 0;
        for (int k = 0; k < balls.length; k += 4) {
            double dx = balls[k] - cx, dy = balls[k + 1] - cy, dz = balls[k + 2] - cz;
            r = Math.max(r, Math.sqrt(dx * dx + dy * dy + dz * dz) + balls[k + 3]);
        }
        return new double[] {cx, cy, cz, r};
    }

    /** How many targets there are. */
    public int count() {
        return count;
    }

    /**
     * Which target the uniform number u in [0, 1) aims at, or -1: the light's own density. u below
     * {@link #AIMED} aims, at the target its place in [0, AIMED) says.
     */
    public int choose(double u) {
        if (count == 0 || u >= AIMED) {
            return -1;
        }
        return Math.min(count - 1, (int) (u / AIMED * count));
    }

    /**
     * A direction from o spread uniformly over the cone target j's ball fills, from u1 (the angle off
     * its axis) and u2 (around it), into {@code out}'s direction; false where o lies in the ball, which
     * has no cone.
     */
    public boolean aim(int j, double ox, double oy, double oz, double u1, double u2, LightRay out) {
        int k = 4 * j;
        double dx = balls[k] - ox, dy = balls[k + 1] - oy, dz = balls[k + 2] - oz;
        double d2 = dx * dx + dy * dy + dz * dz, r2 = balls[k + 3] * balls[k + 3];
        if (d2 <= r2) {
            return false;
        }
        double inv = 1 / Math.sqrt(d2);
        double[] w = out.scratch;
        Cone.sample(dx * inv, dy * inv, dz * inv, Cone.oneMinusCos(r2 / d2), u1, u2, out.frame, w);
        out.setDirection(w[0], w[1], w[2]);
        return true;
    }

    /**
     * A light at infinity's ray along unit d, from the disc of radius {@code sceneRadius} that faces it
     * at that distance from the scene's centre c ({@link Lights#leaving}): its origin moved to a point
     * spread uniformly over target j's shadow on that disc, from u1 and u2.
     */
    public void aimAcross(int j, double cx, double cy, double cz, double sceneRadius, double u1, double u2,
                          LightRay out) {
        int k = 4 * j;
        double tx = -out.dirX, ty = -out.dirY, tz = -out.dirZ; // towards the light
        double back = (cx - balls[k]) * tx + (cy - balls[k + 1]) * ty + (cz - balls[k + 2]) * tz + sceneRadius;
        double[] p = out.scratch;
        Directions.onDisc(balls[k] + tx * back, balls[k + 1] + ty * back, balls[k + 2] + tz * back, tx, ty, tz,
                balls[k + 3], u1, u2, out.frame, p);
        out.setOrigin(p[0], p[1], p[2]);
    }

    /**
     * The density per unit area of the disc point a light at infinity's ray along unit d leaves from,
     * for the ray through point p, where the light's own density of it is {@code own}: the mixture of
     * the own density and the targets' shadows ({@link #aimAcross}).
     */
    public double pdfAcross(double px, double py, double pz, double dx, double dy, double dz, double own) {
        if (count == 0) {
            return own;
        }
        double aimed = 0;
        for (int k = 0; k < 4 * count; k += 4) {
            double vx = balls[k] - px, vy = balls[k + 1] - py, vz = balls[k + 2] - pz;
            double along = vx * dx + vy * dy + vz * dz, r2 = balls[k + 3] * balls[k + 3];
            if (vx * vx + vy * vy + vz * vz - along * along <= r2) {
                aimed += 1 / (Math.PI * r2);
            }
        }
        return (1 - AIMED) * own + AIMED * aimed / count;
    }

    /**
     * The density per solid angle with which a ray from o leaves along unit w, where the light's own
     * density of w is {@code own}: the mixture of the own density and the targets' cones. A target
     * whose ball holds o, having no cone, leaves by the light's own density, as {@link #aim} does.
     */
    public double pdf(double ox, double oy, double oz, double wx, double wy, double wz, double own) {
        if (count == 0) {
            return own;
        }
        double aimed = 0;
        for (int k = 0; k < 4 * count; k += 4) {
            double dx = balls[k] - ox, dy = balls[k + 1] - oy, dz = balls[k + 2] - oz;
            double d2 = dx * dx + dy * dy + dz * dz, r2 = balls[k + 3] * balls[k + 3];
            if (d2 <= r2) {
                aimed += own;
                continue;
            }
            double inv = 1 / Math.sqrt(d2), sin2 = r2 / d2;
            if (Cone.contains(dx * inv, dy * inv, dz * inv, sin2, wx, wy, wz)) {
                aimed += Cone.pdf(Cone.oneMinusCos(sin2));
            }
        }
        return (1 - AIMED) * own + AIMED * aimed / count;
    }
}
