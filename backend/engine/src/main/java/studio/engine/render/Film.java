package studio.engine.render;

/**
 * The linear-light framebuffer: one RGB triple of doubles per pixel, row-major from the top-left.
 * Non-finite values never get in: {@link #set} rejects them and counts them instead. A film holds
 * a whole image, or only one tile of it ({@link #ofTile}), addressed in the image's coordinates
 * either way: a worker that renders one tile for another machine needs the tile's 24 KB (32x32),
 * not the whole image's 200 MB (4K).
 */
public final class Film {

    private final int width, height;
    /** The image coordinates of this film's top-left pixel. */
    private final int x0, y0;
    private final double[] rgb;

    public Film(int width, int height) {
        this(0, 0, width, height);
    }

    private Film(int x0, int y0, int width, int height) {
        this.x0 = x0;
        this.y0 = y0;
        this.width = width;
        this.height = height;
        this.rgb = new double[3 * width * height];
    }

    /** A film of the tile's pixels only, addressed in the image's coordinates. */
    public static Film ofTile(TileRect tile) {
        return new Film(tile.x(), tile.y(), tile.width(), tile.height());
    }

    /** The width of the pixels this film holds (the image's, unless it holds one tile). */
    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Stores a pixel; returns false (and stores black) if any component is NaN or infinite. */
    public boolean set(int x, int y, double r, double g, double b) {
        int i = 3 * ((y - y0) * width + x - x0);
        if (Double.isFinite(r) && Double.isFinite(g) && Double.isFinite(b)) {
            rgb[i] = r;
            rgb[i + 1] = g;
            rgb[i + 2] = b;
            return true;
        }
        rgb[i] = rgb[i + 1] = rgb[i + 2] = 0;
        return false;
    }

    /**
     * The pixels of {@code tile} (which this film holds), row-major RGB triples from its top-left, in
     * linear light: a copy, {@code 3 * width * height} long, taken a row at a time.
     */
    public double[] pixels(TileRect tile) {
        int rowLength = 3 * tile.width();
        double[] out = new double[rowLength * tile.height()];
        for (int row = 0; row < tile.height(); row++) {
            int from = 3 * ((tile.y() + row - y0) * width + tile.x() - x0);
            System.arraycopy(rgb, from, out, row * rowLength, rowLength);
        }
        return out;
    }

    /**
     * Stores the pixels of {@code tile} (which this film holds) from {@code rgb}, row-major RGB
     * triples from its top-left as {@link #pixels} gives them, each as {@link #set} does (a pixel
     * with a NaN or infinite component as black).
     */
    public void setPixels(TileRect tile, double[] rgb) {
        if (rgb.length != 3 * tile.width() * tile.height()) {
            throw new IllegalArgumentException(
                    rgb.length + " values for a " + tile.width() + "x" + tile.height() + " tile");
        }
        int i = 0;
        for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
            for (int x = tile.x(); x < tile.x() + tile.width(); x++, i += 3) {
                set(x, y, rgb[i], rgb[i + 1], rgb[i + 2]);
            }
        }
    }

    /** Component c (0 red, 1 green, 2 blue) of pixel (x, y), in linear light. */
    public double get(int x, int y, int c) {
        return rgb[3 * ((y - y0) * width + x - x0) + c];
    }
}
