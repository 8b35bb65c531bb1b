package studio.engine.math;

/** A colour or radiance in linear light (not sRGB), components usually in [0, 1] but unbounded. */
public record Rgb(double r, double g, double b) {

    public static final Rgb BLACK = new Rgb(0, 0, 0);
    public static final Rgb WHITE = new Rgb(1, 1, 1);

    /** Decodes an 8-bit sRGB colour such as the editor's colour picker gives into linear light. */
    public static Rgb fromSrgb8(int r, int g, int b) {
        return new Rgb(Srgb.toLinear(r / 255.0), Srgb.toLinear(g / 255.0), Srgb.toLinear(b / 255.0));
    }

    public Rgb plus(Rgb o) {
        return new Rgb(r + o.r, g + o.g, b + o.b);
    }

    public Rgb times(Rgb o) {
        return new Rgb(r * o.r, g * o.g, b * o.b);
    }

    public Rgb times(double s) {
        return new Rgb(r * s, g * s, b * s);
    }

    public double max() {
        return Math.max(r, Math.max(g, b));
    }

    public boolean isBlack() {
        return r == 0 && g == 0 && b == 0;
    }
}
