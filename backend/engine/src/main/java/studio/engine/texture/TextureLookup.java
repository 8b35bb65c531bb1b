package studio.engine.texture;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Shape;
import studio.engine.geometry.TextureCoordinates;

/**
 * A texture's colour at the hit being shaded, averaged over the pixel sample's footprint there: the
 * ray cone's circular cross-section of width {@code w} (Akenine-Möller et al., "Texture Level of
 * Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20) laid on the surface as an
 * ellipse, w / |cos| long along the ray's direction and w across it (their anisotropic cones,
 * "Improved Shader and Texture Level of Detail Using Ray Cones", JCGT 2021), whose two axes are taken
 * into texture space through dp/du and dp/dv; the box around that ellipse is what the texture averages.
 *
 * <p>One per worker thread; reused, so a lookup allocates nothing.
 */
public final class TextureLookup {

    /** Below this |cos| a grazing footprint counts as this long: finite, and already wider than any texture's detail. */
    private static final double MIN_COS = 1e-9;

    private final TextureCoordinates coords = new TextureCoordinates();
    private final double[] rgb = new double[3];
    /** The colour found by the last {@link #lookup}, linear. */
    public double r, g, b;

    /**
     * Looks {@code texture} up at {@code hit} on {@code shape}, seen along the unit direction
     * (dx, dy, dz), where the ray cone is {@code width} wide (world units; 0 point-samples), into r, g, b.
     */
    public void lookup(Texture texture, Shape shape, Hit hit, double dx, double dy, double dz, double width) {
        TextureCoordinates c = coords;
        shape.textureCoordinates(hit, c);
        double nx = hit.gx, ny = hit.gy, nz = hit.gz;
        double cos = dx * nx + dy * ny + dz * nz;
        // the ellipse's long axis: the direction's part in the tangent plane, w / |cos| long
        double tx = dx - cos * nx, ty = dy - cos * ny, tz = dz - cos * nz;
        double sin = Math.sqrt(tx * tx + ty * ty + tz * tz);
        if (sin > 1e-12) {
            tx /= sin; ty /= sin; tz /= sin;
        } else { // head-on: a circle; any tangent will do
            boolean useX = Math.abs(nx) < 0.9;
            double ax = useX ? 1 : 0, ay = useX ? 0 : 1;
            tx = ay * nz; ty = -ax * nz; tz = ax * ny - ay * nx;
            double len = Math.sqrt(tx * tx + ty * ty + tz * tz);
            tx /= len; ty /= len; tz /= len;
        }
        double along = width / Math.max(Math.abs(cos), MIN_COS);
        double bx = ny * tz - nz * ty, by = nz * tx - nx * tz, bz = nx * ty - ny * tx;
        double e = c.dpdux * c.dpdux + c.dpduy * c.dpduy + c.dpduz * c.dpduz;
        double f = c.dpdux * c.dpdvx + c.dpduy * c.dpdvy + c.dpduz * c.dpdvz;
        double gg = c.dpdvx * c.dpdvx + c.dpdvy * c.dpdvy + c.dpdvz * c.dpdvz;
        double det = e * gg - f * f;
        double widthU, widthV;
        if (det > 0 && Double.isFinite(det)) {
            // each axis in texture space: the least-squares (u, v) step that moves p along it
            double au1 = along * (tx * c.dpdux + ty * c.dpduy + tz * c.dpduz);
            double av1 = along * (tx * c.dpdvx + ty * c.dpdvy + tz * c.dpdvz);
            double au2 = width * (bx * c.dpdux + by * c.dpduy + bz * c.dpduz);
            double av2 = width * (bx * c.dpdvx + by * c.dpdvy + bz * c.dpdvz);
            double du1 = (gg * au1 - f * av1) / det, dv1 = (e * av1 - f * au1) / det;
            double du2 = (gg * au2 - f * av2) / det, dv2 = (e * av2 - f * au2) / det;
            widthU = Math.sqrt(du1 * du1 + du2 * du2);
            widthV = Math.sqrt(dv1 * dv1 + dv2 * dv2);
        } else { // no texture-space frame here (a sphere's pole): the footprint covers every u and v
            widthU = widthV = Double.POSITIVE_INFINITY;
        }
        texture.filtered(c.u, c.v, widthU, widthV, c.metresU, c.metresV, c.wrapsU, rgb);
        r = rgb[0];
        g = rgb[1];
        b = rgb[2];
    }
}
