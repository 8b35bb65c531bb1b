package studio.engine.render;

/**
 * The linear-light framebuffer: one RGB triple of doubles per pixel, row-major from the top-left.
 * Non-finite values never get in: {@link #set} rejects them and counts them instead.
 */
public final class Film {

    private final int width, height;
    private final double[] rgb;

    public Film(int width, int height) {
        this.width = width;
        this.height = height;
        this.rgb = new double[3 * width * height];
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Stores a pixel; returns false (and stores black) if any component is NaN or infinite. */
    public boolean set(int x, int y, double r, double g, double b) {
        int i = 3 * (y * width + x);
        if (Double.isFinite(r) && Double.isFinite(g) && Double.isFinite(b)) {
            rgb[i] = r;
            rgb[i + 1] = g;
            rgb[i + 2] = b;
            return true;
        }
        rgb[i] = rgb[i + 1] = rgb[i + 2] = 0;
        return false;
    }

    /** Component c (0 red, 1 green, 2 blue) of pixel (x, y), in linear light. */
    public double get(int x, int y, int c) {
        return rgb[3 * (y * width + x) + c];
    }
}
