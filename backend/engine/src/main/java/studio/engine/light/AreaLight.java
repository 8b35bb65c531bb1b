package studio.engine.light;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/**
 * A rectangle of light, {@code width} x {@code height} metres, centred at {@code position} and
 * facing {@code lookAt}, as three.js's RectAreaLight: its front normal points at lookAt, its width
 * runs along the horizontal x axis = normalize(up x back) with up = (0, 1, 0) and back =
 * position - lookAt (world x when it faces straight up or down, where three.js ends at the same
 * axis), and its height along back x x. It emits from its front only, unless {@code twoSided}.
 *
 * <p>It is a Lambertian emitter: what it gives a point falls with the cosine at the light,
 * cos_l = -(normal . l), l the direction from the point to the light. With fall-off its radiance is
 * I / (width height), so a small one gives I cos_l / d^2: a point light's I / d^2 on its axis.
 * Without fall-off a point that sees all of it gets colour * intensity * cos_l (times the cosine at
 * the point), averaged over the rectangle.
 */
public record AreaLight(Vec3 position, double width, double height, Vec3 lookAt, Rgb color, double intensity,
                        boolean falloff, boolean twoSided) implements Light {

    public AreaLight {
        if (!position.isFinite() || !lookAt.isFinite()) {
            throw new IllegalArgumentException("light position and lookAt must be finite: " + position + ", " + lookAt);
        }
        if (!(width > 0) || !(height > 0) || !Double.isFinite(width) || !Double.isFinite(height)) {
            throw new IllegalArgumentException("an area light's size must be finite and positive: " + width + " x " + height);
        }
        if (!(position.minus(lookAt).length() > 0)) {
            throw new IllegalArgumentException("an area light's lookAt must differ from its position: " + lookAt);
        }
        Light.checkColorAndIntensity(color, intensity);
    }

    /** The front normal: unit, from position towards lookAt. */
    public Vec3 normal() {
        return lookAt.minus(position).normalized();
    }

    /** The unit axis the width runs along (see the class comment). */
    public Vec3 widthAxis() {
        Vec3 back = normal().negated();
        Vec3 x = new Vec3(0, 1, 0).cross(back);
        return x.length() > 1e-12 ? x.normalized() : new Vec3(1, 0, 0);
    }

    /** The unit axis the height runs along: back x widthAxis. */
    public Vec3 heightAxis() {
        return normal().negated().cross(widthAxis()).normalized();
    }
}
