package studio.engine.accel;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;

/** Spheres as {@link Primitives}, through the engine's sphere test ({@link Sphere#intersect}). */
public final class SpherePrimitives implements Primitives {

    private final double[] spheres;
    private final double[] boxes;
    private final Hit hit = new Hit();

    /** Spheres as (cx, cy, cz, radius) quadruples. */
    public SpherePrimitives(double[] spheres) {
        this.spheres = spheres.clone();
        int n = spheres.length / 4;
        boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            Sphere s = new Sphere(new studio.engine.math.Vec3(spheres[4 * i], spheres[4 * i + 1], spheres[4 * i + 2]),
                    spheres[4 * i + 3]);
            s.bounds().copyTo(boxes, 6 * i);
        }
    }

    @Override
    public double distance(int p, Ray ray, double tMax) {
        int o = 4 * p;
        return Sphere.intersect(spheres[o], spheres[o + 1], spheres[o + 2], spheres[o + 3], ray, tMax, hit)
                ? hit.t : Double.NaN;
    }

    @Override
    public double[] boxes() {
        return boxes;
    }

    @Override
    public int count() {
        return spheres.length / 4;
    }
}
