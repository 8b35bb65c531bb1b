package studio.engine.light;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/**
 * A point light. Without fall-off its irradiance is colour * intensity at any distance (as
 * POV-Ray's default); with fall-off it is divided by the squared distance. Its shadows are hard.
 */
public record PointLight(Vec3 position, Rgb color, double intensity, boolean falloff) implements Light {

    public PointLight {
        if (!position.isFinite()) {
            throw new IllegalArgumentException("light position must be finite: " + position);
        }
        Light.checkColorAndIntensity(color, intensity);
    }
}
