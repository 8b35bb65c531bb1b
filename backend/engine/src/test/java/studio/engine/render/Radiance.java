package studio.engine.render;

import studio.engine.geometry.Ray;
import studio.engine.math.Rgb;

/** The tests' view of an integrator: the radiance along one camera ray, as a colour. */
final class Radiance {

    private Radiance() {
    }

    /** Radiance arriving along a camera ray (allocates; the render loop reads the integrator's slots). */
    static Rgb of(Integrator integrator, Ray ray) {
        integrator.trace(ray, 0, 1.0);
        return new Rgb(integrator.r(), integrator.g(), integrator.b());
    }
}
