package studio.engine.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/** The footprint: the cone's width across, width / |cos| along the ray, taken into texture space. */
class TextureLookupTest {

    private static final Plane FLOOR = new Plane(Vec3.ZERO, new Vec3(0, 1, 0));
    /** A 0 / 1 checker: the lookup's red is the second colour's share. */
    private static final CheckerTexture CHECKS = new CheckerTexture(Rgb.BLACK, Rgb.WHITE, 1);

    private static double share(double dx, double dy, double dz, double x, double z, double width) {
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= len; dy /= len; dz /= len;
        Ray ray = new Ray().set(x - dx * 10 / -dy, 10, z - dz * 10 / -dy, dx, dy, dz);
        Hit hit = new Hit();
        FLOOR.intersect(ray, Double.POSITIVE_INFINITY, hit);
        TextureLookup lookup = new TextureLookup();
        lookup.lookup(CHECKS, FLOOR, hit, dx, dy, dz, width);
        return lookup.r;
    }

    @Test
    void aPointFootprintReadsItsSquare() {
        assertEquals(0, share(0, -1, 0, 0.5, -0.5, 0), 1e-12);
        assertEquals(1, share(0, -1, 0, 1.5, -0.5, 0), 1e-12);
    }

    @Test
    void headOnTheFootprintIsTheConesWidth() {
        // a box 1 wide centred on a corner of four squares: half of it each colour
        assertEquals(0.5, share(0, -1, 0, 1, -1, 1), 1e-9);
        // 0.5 wide, centred 0.25 from a square's edge along x: all in one square
        assertEquals(0, share(0, -1, 0, 0.5, -0.5, 0.5), 1e-9);
    }

    @Test
    void atAGrazingAngleTheFootprintStretchesAlongTheRay() {
        // 60 degrees from the normal, looking along -z: 0.5 wide across (x), 1 long along z
        double dy = -Math.cos(Math.toRadians(60)), dz = -Math.sin(Math.toRadians(60));
        assertEquals(0, share(0, dy, dz, 0.5, -0.5, 0.45), 1e-9); // 0.9 along z: inside the square
        assertEquals(0.5, share(0, dy, dz, 0.5, -1, 0.5), 1e-9); // 1 along z, centred on an edge: half
    }
}
