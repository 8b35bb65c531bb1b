package studio.engine.light;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/**
 * A sphere of light (a point light with a radius): seen by camera and specular rays as
 * colour * intensity, and lighting a point from the cap of it that point sees. With fall-off it
 * gives what a point light at its centre gives, I / d^2, exactly in the limit of a small radius; the
 * sphere's radiance is then I / (pi r^2). Without fall-off every direction of the cap counts as the
 * whole light, so a point that sees all of the cap gets colour * intensity (times the cosine), as
 * from a point light.
 */
public record SphereLight(Vec3 position, double radius, Rgb color, double intensity, boolean falloff)
        implements Light {

    public SphereLight {
        if (!position.isFinite()) {
            throw new IllegalArgumentException("light position must be finite: " + position);
        }
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("a sphere light's radius must be finite and positive: " + radius);
        }
        Light.checkColorAndIntensity(color, intensity);
    }
}
