package studio.engine.math;

/** Floating-point error bounds in pbrt's notation. */
public final class Fp {

    /** Unit roundoff of double precision, u = 2^-53. */
    public static final double UNIT_ROUNDOFF = Math.ulp(1.0) / 2;

    private Fp() {
    }

    /** gamma(n) = n*u / (1 - n*u): bounds the relative error of n chained roundings. */
    public static double gamma(int n) {
        double nu = n * UNIT_ROUNDOFF;
        return nu / (1 - nu);
    }
}
