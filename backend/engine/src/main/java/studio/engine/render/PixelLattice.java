package studio.engine.render;

/**
 * The pixels (x, y) of an image with x and y both {@code offset} modulo {@code step}: every pixel
 * for step 1, one pixel of each step x step block otherwise. A live view refines coarse to fine by
 * rendering nested lattices (a mosaic, as POV-Ray's preview does): first one pixel in 64, then the
 * rest of every fourth, second and first, each pass only the pixels the one before did not take.
 * Each pixel is seeded from its position, so the finished film is the plain render's, and every
 * pass before it cost only its new pixels.
 *
 * @param step   the lattice's spacing, at least 1
 * @param offset where each block's pixel sits, 0 .. step - 1
 */
public record PixelLattice(int step, int offset) {

    /** Every pixel. */
    public static final PixelLattice ALL = new PixelLattice(1, 0);

    public PixelLattice {
        if (step < 1 || offset < 0 || offset >= step) {
            throw new IllegalArgumentException("a lattice needs step >= 1 and 0 <= offset < step; got step " + step
                    + ", offset " + offset);
        }
    }

    /** Whether pixel (x, y) is on this lattice. */
    public boolean contains(int x, int y) {
        return Math.floorMod(x - offset, step) == 0 && Math.floorMod(y - offset, step) == 0;
    }

    /** Whether every pixel of this lattice is on {@code other}. */
    public boolean within(PixelLattice other) {
        return step % other.step == 0 && Math.floorMod(offset - other.offset, other.step) == 0;
    }

    /** How many of the coordinates 0 .. size - 1 are on the lattice: the width of its image of a row. */
    public int count(int size) {
        return size <= offset ? 0 : (size - offset + step - 1) / step;
    }

    /** The first coordinate at or after {@code from} that is on the lattice. */
    public int first(int from) {
        return from + Math.floorMod(offset - from, step);
    }
}
