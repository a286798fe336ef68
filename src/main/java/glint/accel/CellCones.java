package glint.accel;

import glint.geometry.Primitives;
import java.util.Arrays;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The geometry behind {@link CellMaps}: each direction cell of a cube map of K x K cells a face (and
 * each row of cells and each face) as a cone, its axis and the cosine and sine of its half-angle,
 * and which primitives a ray from a ball may reach in a cell.
 *
 * <p>A ray from o, |o - c| <= r, along d meets the ball (c', R) only if the ray from c along d
 * passes within r + R of c' (the two rays stay r apart at most), so only if the angle between d
 * and c' - c is at most asin((r + R) / |c' - c|), or always where r + R >= |c' - c|. A cell lists
 * the primitive when that cone meets the cell's cone. Each cone's half-angle is the largest angle
 * from its axis to points sampled along the cell's edges (it is reached at a corner; the samples
 * make sure), widened by a slack angle that also covers the rounding of the lookup and the tests.
 */
final class CellCones {

    /** The cones of each cube map's size, made when first asked for. */
    private static final ConcurrentHashMap<Integer, CellCones> MADE = new ConcurrentHashMap<>();

    /** Cells along a cube face's side. */
    final int k;
    /** Angle (radians) every cone is widened by ({@link AggregatePolicy#CELL_CONE_SLACK}). */
    private static final double SLACK = AggregatePolicy.CELL_CONE_SLACK;
    private static final int SAMPLES = 64;

    /** Per cell: axis x, y, z, cos and sin of the half-angle. */
    private final double[] cell;
    /** Per row of a face's cells (fixed u): the same for the whole row. */
    private final double[] row;
    /** Per face: the same for the whole face. */
    private final double[] face = new double[5 * 6];

    /** The cones of a cube map of k x k cells a face. */
    static CellCones of(int k) {
        return MADE.computeIfAbsent(k, CellCones::new);
    }

    private CellCones(int k) {
        this.k = k;
        cell = new double[5 * 6 * k * k];
        row = new double[5 * 6 * k];
        for (int f = 0; f < 6; f++) {
            cone(f, -1, 1, -1, 1, face, 5 * f);
            for (int i = 0; i < k; i++) {
                cone(f, -1 + 2.0 * i / k, -1 + 2.0 * (i + 1) / k, -1, 1, row, 5 * (f * k + i));
                for (int j = 0; j < k; j++) {
                    double u0 = -1 + 2.0 * i / k, u1 = -1 + 2.0 * (i + 1) / k;
                    double v0 = -1 + 2.0 * j / k, v1 = -1 + 2.0 * (j + 1) / k;
                    cone(f, u0, u1, v0, v1, cell, 5 * ((f * k + i) * k + j));
                }
            }
        }
    }

    /** The cone around the directions of face f with coordinates in [u0, u1] x [v0, v1]. */
    private static void cone(int f, double u0, double u1, double v0, double v1, double[] out, int at) {
        double[] axis = direction(f, 0.5 * (u0 + u1), 0.5 * (v0 + v1));
        double smallest = 1; // the cosine of the largest angle
        for (int s = 0; s <= SAMPLES; s++) {
            double a = (double) s / SAMPLES;
            double u = u0 + a * (u1 - u0), v = v0 + a * (v1 - v0);
            smallest = Math.min(smallest, cosine(axis, f, u, v0));
            smallest = Math.min(smallest, cosine(axis, f, u, v1));
            smallest = Math.min(smallest, cosine(axis, f, u0, v));
            smallest = Math.min(smallest, cosine(axis, f, u1, v));
        }
        double half = Math.acos(Math.max(-1, smallest)) + SLACK;
        System.arraycopy(axis, 0, out, at, 3);
        out[at + 3] = Math.cos(half);
        out[at + 4] = Math.sin(half);
    }

    /** The unit direction of face f at (u, v), as {@link CellFilter#cellOf} reads it. */
    private static double[] direction(int f, double u, double v) {
        double sign = f % 2 == 0 ? 1 : -1;
        double[] d = switch (f / 2) {
            case 0 -> new double[] {sign, u, v};
            case 1 -> new double[] {u, sign, v};
            default -> new double[] {u, v, sign};
        };
        double length = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        return new double[] {d[0] / length, d[1] / length, d[2] / length};
    }

    /** The cosine of the angle between the unit vector a and the direction of face f at (u, v). */
    private static double cosine(double[] a, int f, double u, double v) {
        double sign = f % 2 == 0 ? 1 : -1;
        double dot = switch (f / 2) {
            case 0 -> a[0] * sign + a[1] * u + a[2] * v;
            case 1 -> a[0] * u + a[1] * sign + a[2] * v;
            default -> a[0] * u + a[1] * v + a[2] * sign;
        };
        return Math.min(1, dot / Math.sqrt(1 + u * u + v * v));
    }

    /**
     * Writes primitive q's ball to {@code balls} from 4q: the kind's bounding ball for a closed
     * kind, the ball around its box otherwise.
     */
    static void ballOf(Primitives p, int q, double[] scratch, double[] balls) {
        if (p.closed(q)) {
            p.kind(p.kindOf(q)).boundingBall(p.indexOf(q), scratch);
            System.arraycopy(scratch, 0, balls, 4 * q, 4);
            return;
        }
        p.bounds(q, scratch, 0);
        boxBall(scratch, 0, balls, 4 * q);
    }

    /** Writes the ball around the box at {@code box[b]} (min x, y, z, max x, y, z) to {@code ball} from {@code at}. */
    static void boxBall(double[] box, int b, double[] ball, int at) {
        double ex = 0.5 * (box[b + 3] - box[b]), ey = 0.5 * (box[b + 4] - box[b + 1]);
        double ez = 0.5 * (box[b + 5] - box[b + 2]);
        ball[at] = 0.5 * (box[b] + box[b + 3]);
        ball[at + 1] = 0.5 * (box[b + 1] + box[b + 4]);
        ball[at + 2] = 0.5 * (box[b + 2] + box[b + 5]);
        ball[at + 3] = Math.nextUp(Math.sqrt(ex * ex + ey * ey + ez * ez)) * (1 + 1e-12);
    }

    /**
     * Whether a ray from the ball (c, reach) may reach the ball (b, radius) in a cell still open
     * in {@code lists}; with {@code q} >= 0, adds q to every such cell instead (returning whether
     * there was one).
     */
    boolean reach(double cx, double cy, double cz, double reach, double[] balls, int at, int q, Lists lists) {
        double ex = balls[at] - cx, ey = balls[at + 1] - cy, ez = balls[at + 2] - cz;
        double distance = Math.sqrt(ex * ex + ey * ey + ez * ez);
        double sum = reach + balls[at + 3];
        boolean met = false;
        int cap = lists.cap;
        if (!(sum < distance)) { // overlapping balls: every direction
            for (int c = 0; c < 6 * k * k; c++) {
                if (lists.counts[c] <= cap) {
                    if (q < 0) {
                        return true;
                    }
                    met = true;
                    lists.add(c, q);
                }
            }
            return met;
        }
        ex /= distance;
        ey /= distance;
        ez /= distance;
        double sinB = sum / distance, cosB = Math.sqrt(1 - sinB * sinB);
        for (int f = 0; f < 6; f++) {
            if (lists.openInFace[f] == 0 || !meets(face, 5 * f, ex, ey, ez, cosB, sinB)) {
                continue;
            }
            for (int row = f * k, rows = row + k; row < rows; row++) {
                if (lists.openInRow[row] == 0 || !meets(this.row, 5 * row, ex, ey, ez, cosB, sinB)) {
                    continue;
                }
                for (int c = row * k, end = c + k; c < end; c++) {
                    if (lists.counts[c] <= cap && meets(cell, 5 * c, ex, ey, ez, cosB, sinB)) {
                        if (q < 0) {
                            return true;
                        }
                        met = true;
                        lists.add(c, q);
                    }
                }
            }
        }
        return met;
    }

    /** Whether the cone at {@code at} meets the cone about e of half-angle B: angle(axis, e) <= A + B. */
    private static boolean meets(double[] cones, int at, double ex, double ey, double ez, double cosB, double sinB) {
        double cos = cones[at] * ex + cones[at + 1] * ey + cones[at + 2] * ez;
        return cos >= cones[at + 3] * cosB - cones[at + 4] * sinB;
    }

    /**
     * One ball's cells as they are filled: up to {@code cap} primitives a cell, its count going one
     * past the cap at most (the cell is then closed: it falls back), and how many cells are still
     * open in each row and face.
     */
    static final class Lists {

        final int k, cap;
        final int[] lists;
        final int[] counts;
        final int[] openInRow;
        final int[] openInFace = new int[6];
        int open;

        Lists(int k, int cap) {
            this.k = k;
            this.cap = cap;
            lists = new int[6 * k * k * cap];
            counts = new int[6 * k * k];
            openInRow = new int[6 * k];
        }

        void reset() {
            Arrays.fill(counts, 0);
            Arrays.fill(openInRow, k);
            Arrays.fill(openInFace, k * k);
            open = counts.length;
        }

        void add(int c, int q) {
            int count = counts[c];
            if (count < cap) {
                lists[c * cap + count] = q;
                counts[c] = count + 1;
            } else if (count == cap) {
                counts[c] = count + 1;
                openInRow[c / k]--;
                openInFace[c / (k * k)]--;
                open--;
            }
        }
    }
}
