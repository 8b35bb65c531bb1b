package studio.engine.texture;

import studio.engine.math.Rgb;

/**
 * Squares of two colours, {@code size} metres a side, {@code first} where u and v both start (the
 * squares are counted in the surface's metres: see {@link studio.engine.geometry.TextureCoordinates}).
 * Around a sphere the count is rounded to an even whole number, so the squares meet at the seam.
 *
 * <p>Filtered in closed form (pbrt-v3's Checkerboard2DTexture, "closed-form box filtering"): the
 * integral of the square wave over the footprint's box, per axis, gives the share of the second
 * colour exactly, so a plane of checks running to the horizon fades to the mean, never to moiré.
 */
public record CheckerTexture(Rgb first, Rgb second, double size) implements Texture {

    public CheckerTexture {
        if (first == null || second == null) {
            throw new IllegalArgumentException("a checker needs two colours");
        }
        if (!(size > 0) || !Double.isFinite(size)) {
            throw new IllegalArgumentException("checker size must be finite and positive: " + size);
        }
    }

    @Override
    public void filtered(double u, double v, double widthU, double widthV, double metresU, double metresV,
                         boolean wrapsU, double[] out) {
        double perU = metresU / size, perV = metresV / size;
        if (wrapsU) {
            perU = 2 * Math.max(1, Math.rint(perU / 2));
        }
        double s = u * perU, t = v * perV;
        double ds = 0.5 * widthU * perU, dt = 0.5 * widthV * perV;
        double share = secondShare(s, t, ds, dt);
        out[0] = first.r() + share * (second.r() - first.r());
        out[1] = first.g() + share * (second.g() - first.g());
        out[2] = first.b() + share * (second.b() - first.b());
    }

    /**
     * The share of the second colour (squares where floor(s) + floor(t) is odd) in the box
     * [s - ds, s + ds] x [t - dt, t + dt]: exact, from each axis's share of odd squares.
     */
    static double secondShare(double s, double t, double ds, double dt) {
        if (!(ds < 1 && dt < 1)) { // wider than a pair of squares (or not finite): the mean to within 1/2 a pair
            return 0.5;
        }
        double s0 = s - ds, s1 = s + ds, t0 = t - dt, t1 = t + dt;
        if (Math.floor(s0) == Math.floor(s1) && Math.floor(t0) == Math.floor(t1)) {
            return (Math.floor(s) + Math.floor(t)) % 2 == 0 ? 0 : 1; // inside one square
        }
        double oddS = ds > 0 ? (oddIntegral(s1) - oddIntegral(s0)) / (2 * ds) : Math.abs(Math.floor(s) % 2);
        double oddT = dt > 0 ? (oddIntegral(t1) - oddIntegral(t0)) / (2 * dt) : Math.abs(Math.floor(t) % 2);
        return oddS + oddT - 2 * oddS * oddT; // exactly one of the two odd
    }

    /** The integral from 0 to x of the square wave that is 1 where floor(x) is odd. */
    private static double oddIntegral(double x) {
        double half = x / 2, whole = Math.floor(half);
        return whole + 2 * Math.max(half - whole - 0.5, 0);
    }
}
