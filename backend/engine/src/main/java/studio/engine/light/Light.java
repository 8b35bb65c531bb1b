package studio.engine.light;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/**
 * A light: a point ({@link PointLight}), a sphere ({@link SphereLight}) or a rectangle
 * ({@link AreaLight}). Each lights a point with {@code color * intensity}, divided by the squared
 * distance when {@code falloff} is set; a light with size spreads that over its surface so that a
 * very small one lights like a point light of the same colour and intensity at its position (for a
 * rectangle: a point on its axis, in front of it). How each is sampled is {@link LightSampler}'s.
 */
public sealed interface Light permits PointLight, SphereLight, AreaLight {

    /** The light's centre. */
    Vec3 position();

    Rgb color();

    double intensity();

    /** Whether what it gives falls with the squared distance. */
    boolean falloff();

    /** Whether the light has a size, and so soft shadows (a point light has none). */
    default boolean soft() {
        return !(this instanceof PointLight);
    }

    /** The checks every light's colour and intensity pass. */
    static void checkColorAndIntensity(Rgb color, double intensity) {
        if (!(intensity >= 0) || !Double.isFinite(intensity)) {
            throw new IllegalArgumentException("light intensity must be finite and non-negative: " + intensity);
        }
        if (color == null || !(color.r() >= 0 && color.g() >= 0 && color.b() >= 0) || !Double.isFinite(color.max())) {
            throw new IllegalArgumentException("light colour must be finite and non-negative: " + color);
        }
    }
}
