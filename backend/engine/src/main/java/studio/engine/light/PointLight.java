package studio.engine.light;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/**
 * A point light. Without fall-off its irradiance is colour * intensity at any distance (as
 * POV-Ray's default); with fall-off it is divided by the squared distance.
 */
public record PointLight(Vec3 position, Rgb color, double intensity, boolean falloff) {

    public PointLight {
        if (!position.isFinite()) {
            throw new IllegalArgumentException("light position must be finite: " + position);
        }
        if (!(intensity >= 0) || !Double.isFinite(intensity)) {
            throw new IllegalArgumentException("light intensity must be finite and non-negative: " + intensity);
        }
        if (color == null || !(color.r() >= 0 && color.g() >= 0 && color.b() >= 0) || !Double.isFinite(color.max())) {
            throw new IllegalArgumentException("light colour must be finite and non-negative: " + color);
        }
    }

    /** Colour times intensity: the radiance scale before fall-off. */
    public Rgb power() {
        return color.times(intensity);
    }
}
