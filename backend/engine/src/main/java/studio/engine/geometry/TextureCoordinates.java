package studio.engine.geometry;

/**
 * Where a hit lies in its surface's texture space: (u, v), and how the surface point moves per unit
 * of each (dp/du, dp/dv, world units), which maps a footprint on the surface into texture space.
 * Filled by {@link Shape#textureCoordinates} for the final hit being shaded only, never in traversal;
 * mutable and reused, one per worker thread.
 *
 * <p>{@code metresU}/{@code metresV}: the metres one unit of u and v stands for on this shape (1 on
 * planes and meshes, the face's sides on a box, the equator's and a meridian's length on a sphere),
 * which a texture sized in metres reads; {@code wrapsU}: u is periodic (a sphere's longitude), so a
 * pattern that repeats a whole number of times around meets itself at the seam.
 */
public final class TextureCoordinates {

    public double u, v;
    public double dpdux, dpduy, dpduz;
    public double dpdvx, dpdvy, dpdvz;
    public double metresU = 1, metresV = 1;
    public boolean wrapsU;

    void set(double u, double v, double dpdux, double dpduy, double dpduz, double dpdvx, double dpdvy, double dpdvz,
             double metresU, double metresV, boolean wrapsU) {
        this.u = u;
        this.v = v;
        this.dpdux = dpdux; this.dpduy = dpduy; this.dpduz = dpduz;
        this.dpdvx = dpdvx; this.dpdvy = dpdvy; this.dpdvz = dpdvz;
        this.metresU = metresU;
        this.metresV = metresV;
        this.wrapsU = wrapsU;
    }
}
