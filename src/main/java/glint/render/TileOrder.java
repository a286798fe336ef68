package glint.render;

/**
 * The order in which a frame's tiles are handed out: spread over the whole frame, so that the tiles
 * done at any moment are a fair sample of it (some sky, some floor) and the time a render has left,
 * estimated from the share of tiles done, falls steadily instead of growing once the cheap rows are
 * behind. Tile {@code i} of the order is tile {@code i x stride mod n} of the rows, for a stride near
 * n / golden ratio with no factor in common with n (so every tile comes exactly once). The image does
 * not depend on the order: each pixel is computed from its own coordinates alone.
 */
public final class TileOrder {

    private static final double GOLDEN = (1 + Math.sqrt(5)) / 2;

    private TileOrder() {
    }

    /** The tile (row by row, 0 to tiles - 1) handed out {@code i}-th. */
    public static int tile(int i, int tiles, int stride) {
        return (int) ((long) i * stride % tiles);
    }

    /** The stride for a frame of {@code tiles} tiles: the whole number nearest tiles / golden ratio coprime to it. */
    public static int stride(int tiles) {
        int near = Math.max(1, (int) Math.round(tiles / GOLDEN));
        for (int offset = 0; offset < tiles; offset++) {
            if (near + offset < tiles && gcd(near + offset, tiles) == 1) {
                return near + offset;
            }
            if (near - offset >= 1 && gcd(near - offset, tiles) == 1) {
                return near - offset;
            }
        }
        return 1;
    }

    private static int gcd(int a, int b) {
        return b == 0 ? a : gcd(b, a % b);
    }
}
